#include "ui/pages/Iso230_3Page.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <utility>

#include "ui/models/DriftSeriesModel.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/SelectedCampaignLoader.h"
#include "ui/shell/Session.h"
#include "ui/widgets/Iso230_3Plot.h"

namespace driftlab::ui {
namespace {

const QString kEventSource = QStringLiteral("iso230-3");

QDoubleSpinBox* spinBox(QWidget* parent, double min, double max, double value, int decimals,
                        const QString& suffix, const QString& tip) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setToolTip(tip);
    box->setKeyboardTracking(false);  // evaluate on a finished number, not on each digit
    return box;
}

QString stabilisedWords(double time_s) {
    return std::isnan(time_s) ? Iso230_3Page::tr("not stabilised within the run")
                              : Iso230_3Page::tr("stabilised at %1 s").arg(time_s);
}

}  // namespace

Iso230_3Page::Iso230_3Page(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_run(new QComboBox(this)),
      m_window(spinBox(this, 1, 1e6, 600, 0, tr(" s"),
                       tr("W of the stabilisation criterion (iso230-3 --window-s)"))),
      m_tolerance(spinBox(this, 0.001, 1e4, 1, 3, tr(" µm"),
                          tr("D of the stabilisation criterion: the drift must vary by less than "
                             "D over every window W from then on (iso230-3 --tolerance-um)"))),
      m_distance(spinBox(this, 0, 1e4, 0, 1, tr(" mm"),
                         tr("Spindle runs: distance between the two x (and two y) probes along "
                            "the mandrel; gives tilts A and B (iso230-3 --probe-distance-mm)"))),
      m_message(new QLabel(this)),
      m_summary(new QLabel(this)),
      m_warnings(new QLabel(this)),
      m_view(new QTableView(this)),
      m_model(new DriftSeriesModel(this)),
      m_plot(new Iso230_3Plot(this)),
      m_job(new BackgroundJob(this)) {
    m_run->setMinimumContentsLength(12);
    m_distance->setSpecialValueText(tr("not given"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_warnings->setWordWrap(true);
    m_warnings->setStyleSheet(QStringLiteral("color: #a05000"));
    m_view->setModel(m_model);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto* settings = new QHBoxLayout;
    settings->addWidget(new QLabel(tr("Run"), this));
    settings->addWidget(m_run);
    settings->addSpacing(12);
    settings->addWidget(new QLabel(tr("Stabilised: drift varies less than D"), this));
    settings->addWidget(m_tolerance);
    settings->addWidget(new QLabel(tr("over every W"), this));
    settings->addWidget(m_window);
    settings->addSpacing(12);
    settings->addWidget(new QLabel(tr("Probe distance"), this));
    settings->addWidget(m_distance);
    settings->addStretch(1);

    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_plot);
    split->addWidget(m_view);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(settings);
    layout->addWidget(m_message);
    layout->addWidget(m_summary);
    layout->addWidget(m_warnings);
    layout->addWidget(split, 1);

    connect(m_run, &QComboBox::currentIndexChanged, this, &Iso230_3Page::evaluateRun);
    for (QDoubleSpinBox* box : {m_window, m_tolerance, m_distance})
        connect(box, &QDoubleSpinBox::valueChanged, this, &Iso230_3Page::evaluateRun);
    m_loader = new SelectedCampaignLoader(m_session, false, this);
    connect(m_loader, &SelectedCampaignLoader::cleared, this, [this] {
        m_campaign.reset();
        m_run->clear();
        m_message->setText(
            tr("Select a campaign with a moving, spindle or ETVE run in the "
               "campaign tree."));
    });
    connect(m_loader, &SelectedCampaignLoader::loadingStarted, this,
            [this] { m_message->setText(tr("loading the campaign…")); });
    connect(m_loader, &SelectedCampaignLoader::loaded, this, &Iso230_3Page::onLoaded);
    m_loader->reload();
}

Iso230_3Page::~Iso230_3Page() = default;

void Iso230_3Page::showError(const QString& message) {
    m_message->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), kEventSource, message);
}

void Iso230_3Page::onLoaded(const LoadedCampaign& loaded) {
    if (!loaded.campaign) return showError(tr("Loading the campaign: %1").arg(loaded.error));
    m_campaign = std::make_shared<const Campaign>(*loaded.campaign);
    const QString current = m_run->currentData().toString();
    {
        const QSignalBlocker block(m_run);
        m_run->clear();
        for (const Run& run : m_campaign->runs)
            if (iso::hasAxisDrift(run) || iso::hasProbeDrift(run))
                m_run->addItem(QStringLiteral("%1 (%2)").arg(run.id, toString(run.kind)), run.id);
        const int again = m_run->findData(current);
        if (again >= 0) m_run->setCurrentIndex(again);
    }
    evaluateRun();
}

void Iso230_3Page::evaluateRun() {
    if (m_job->isRunning()) {
        m_evaluateAgain = true;
        return;
    }
    m_drift.reset();
    m_model->setDrift({});
    m_plot->clear();
    m_summary->clear();
    m_warnings->clear();
    if (!m_campaign) return;
    const QString runId = m_run->currentData().toString();
    if (runId.isEmpty()) {
        // Not a fault of the campaign (a campaign may have no drift runs): no log entry.
        m_message->setText(tr("No run of campaign %1 is a moving run with positioning "
                              "readings, a spindle run or an ETVE run")
                               .arg(m_campaign->name));
        return emit evaluated();
    }
    iso::DriftSettings settings;
    settings.window_s = m_window->value();
    settings.tolerance_um = m_tolerance->value();
    if (m_distance->value() > 0) settings.probe_distance_mm = m_distance->value();
    m_message->setText(tr("evaluating run %1…").arg(runId));
    auto result = std::make_shared<iso::RunDrift>();
    std::shared_ptr<const Campaign> campaign = m_campaign;
    m_job->start(
        [campaign, runId, settings, result](JobControl& control) {
            control.progress(-1);
            for (const Run& run : campaign->runs)
                if (run.id == runId) *result = iso::evaluateRunDrift(*campaign, run, settings);
        },
        [this, campaign, runId, result] {
            if (std::exchange(m_evaluateAgain, false)) return evaluateRun();
            for (const Run& run : campaign->runs)
                if (run.id == runId) showDrift(run, std::move(*result));
        });
}

void Iso230_3Page::showDrift(const Run& run, iso::RunDrift drift) {
    const QString source =
        tr("run %1 (%2) of %3").arg(run.id, toString(run.kind), m_campaign->name);
    if (!drift.ok()) {
        showError(source + QStringLiteral(": ") + drift.error);
        return emit evaluated();
    }
    const iso::DriftSettings& settings = drift.axis ? drift.axis->settings : drift.probes->settings;
    m_model->setDrift(drift);
    m_plot->show(*m_campaign, run, drift);
    QStringList notes = drift.warnings();
    if (drift.axis) {
        const iso::AxisDriftEvaluation& e = *drift.axis;
        const iso::TargetDrift& max = e.targets[std::size_t(e.max_index)];
        m_message->setText(tr("ISO 230-3 thermal distortion of %1: %2 target/direction series, "
                              "%3 cycles (cycle 0 = cold reference); drift = deviation − "
                              "deviation at cycle 0")
                               .arg(source)
                               .arg(e.targets.size())
                               .arg(e.cycles));
        m_summary->setText(tr("<b>Max drift %1 µm</b> at %2 mm (%3 approach), t = %4 s; range "
                              "%5 µm; %6.")
                               .arg(e.max_drift_um, 0, 'f', 3)
                               .arg(max.target_mm)
                               .arg(max.direction == Direction::Positive ? QStringLiteral("+")
                                                                         : QStringLiteral("−"))
                               .arg(max.drift.max_drift_time_s)
                               .arg(max.drift.range_um, 0, 'f', 3)
                               .arg(stabilisedWords(e.stabilised_time_s)));
    } else {
        const iso::ProbeDriftEvaluation& e = *drift.probes;
        const auto largest = std::max_element(
            e.probes.begin(), e.probes.end(),
            [](const iso::ProbeDrift& a, const iso::ProbeDrift& b) {
                return std::abs(a.drift.max_drift_um) < std::abs(b.drift.max_drift_um);
            });
        m_message->setText(tr("ISO 230-3 drift of %1: %2 probes; drift = value − the probe's "
                              "first sample")
                               .arg(source)
                               .arg(e.probes.size()));
        m_summary->setText(largest == e.probes.end()
                               ? stabilisedWords(e.stabilised_time_s)
                               : tr("<b>Max drift %1 µm</b> on %2, t = %3 s; %4.")
                                     .arg(largest->drift.max_drift_um, 0, 'f', 3)
                                     .arg(largest->channel_id)
                                     .arg(largest->drift.max_drift_time_s)
                                     .arg(stabilisedWords(e.stabilised_time_s)));
        notes += e.notes;
    }
    m_summary->setToolTip(tr("Stabilised: the drift varies by less than %1 µm over every %2 s "
                             "window from then on (DriftLab's criterion)")
                              .arg(settings.tolerance_um)
                              .arg(settings.window_s));
    m_warnings->setText(
        notes.isEmpty() ? QString() : QStringLiteral("⚠ ") + notes.join(QStringLiteral("\n⚠ ")));
    m_drift = std::move(drift);
    emit evaluated();
}

}  // namespace driftlab::ui
