// The Set-up page's machine files (campaign.json without runs, through
// CampaignJson) and the demo set-up.
#include <QFile>
#include <QJsonDocument>
#include <QLabel>
#include <QSaveFile>

#include "core/bundle/BundleError.h"
#include "core/bundle/CampaignJson.h"
#include "core/procedures/ProcedurePlan.h"
#include "core/rig/CampaignSimulator.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ProcedureForm.h"
#include "ui/widgets/ProcedureKeyNumbers.h"
#include "ui/widgets/RigForm.h"

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>

namespace driftlab::ui {
namespace {

const QString kDemoProcedure = QStringLiteral(":/procedures/moving-states-s1-s5.json");
/// The demo's two states: S1 to train a model, S4 (another range) to test it.
const QStringList kDemoStates{QStringLiteral("S1"), QStringLiteral("S4")};
constexpr double kDemoWarmup_s = 3600;
constexpr double kDemoCooldown_s = 1800;
constexpr double kDemoSpeedup = 600;
/// The demo's story: the servo motor heats the screw's fixed end, which the
/// heat-transfer model lacks. 0.5 W/(N·m)² leaves 1.8 µm RMS of residual on
/// held-out S4, about three times the reading noise: the diagnosis names it
/// on other seeds of the rig too, not just the demo's.
constexpr double kDemoMotorHeat = 0.5;

}  // namespace

bool SetupPage::loadMachine(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    try {
        Campaign campaign = bundle::campaignFromJson(file.readAll(), path);
        if (!campaign.runs.empty())
            emit m_session.event(QStringLiteral("info"), QStringLiteral("set-up"),
                                 tr("%1: its %2 run(s) are not part of a machine set-up and were "
                                    "left out")
                                     .arg(path)
                                     .arg(campaign.runs.size()));
        setMachine(campaign);
    } catch (const bundle::BundleException& e) {
        *error = e.error.toString();
        return false;
    }
    m_banner->hide();
    validate();
    emit m_session.event(QStringLiteral("info"), QStringLiteral("set-up"),
                         tr("machine set-up loaded from %1").arg(path));
    return true;
}

bool SetupPage::saveMachine(const QString& path, QString* error) {
    QSaveFile file(path);
    const QByteArray json =
        QJsonDocument(bundle::campaignToJson(machine())).toJson(QJsonDocument::Indented);
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit()) {
        *error = tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    emit m_session.event(QStringLiteral("info"), QStringLiteral("set-up"),
                         tr("machine set-up saved to %1").arg(path));
    return true;
}

void SetupPage::loadDemo() {
    Campaign rig = rig::rigCampaignHeader(rig::RigSpec{}, false);
    rig.name = tr("Demo: simulated X axis");
    setMachine(rig);

    QString error;
    auto procedure = procedures::loadProcedureFile(kDemoProcedure, &error);
    if (!procedure) {  // compiled in: only a broken build gets here
        emit m_session.event(QStringLiteral("error"), QStringLiteral("demo"), error);
        return;
    }
    auto& states = procedure->moving_states->states;
    std::erase_if(states, [](const auto& s) { return !kDemoStates.contains(s.run_id); });
    for (auto& state : states) {
        state.warmup_s = kDemoWarmup_s;
        state.cooldown_s = kDemoCooldown_s;
    }
    procedure->name = tr("Demo: moving states S1 and S4, shortened");
    procedure->description =
        tr("The five-state procedure cut to S1 (210–490 mm at 8000 mm/min) "
           "and S4 (0–210 mm), 1 h warm-up and 30 min cool-down each.");
    m_procedure->setProcedure(*procedure, kDemoProcedure);

    m_rig->setSimulated(true);
    m_rig->seed->setValue(1);
    m_rig->speedup->setValue(kDemoSpeedup);
    m_rig->effects->setText(QStringLiteral("%1=%2").arg(demoHiddenCause()).arg(kDemoMotorHeat));

    double total_s = 0;  // as planned: the measuring passes add to the states' times
    for (const auto& run : procedures::planRuns(*procedure))
        total_s += std::max(run.programme.duration_s, run.duration_s);
    m_banner->setText(
        tr("<b>Demo:</b> the simulated rig is set up: its own X axis and sensors, and a short "
           "procedure (two moving states, %1 of machine time, about %2 at speed-up %3). "
           "The rig hides the servo motor's heat (<i>%4</i>), which the heat-transfer model "
           "lacks. <b>Press Start on the Run page.</b> Then fit a model on the Models page and "
           "diagnose on the Diagnosis page: it names what the model misses, maps where, and "
           "measures the gain of modelling it. Change anything here and press Apply to run "
           "your own set-up.")
            .arg(readableDuration(total_s), readableDuration(total_s / kDemoSpeedup))
            .arg(kDemoSpeedup)
            .arg(demoHiddenCause()));
    m_banner->show();
    apply();
}

QString SetupPage::demoHiddenCause() {
    return QStringLiteral("motor_heat");
}

bool SetupPage::demoBannerShown() const {
    return !m_banner->isHidden();
}

}  // namespace driftlab::ui
