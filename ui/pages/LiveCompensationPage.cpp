#include "ui/pages/LiveCompensationPage.h"

#include <algorithm>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>
#include <memory>

#include "acquisition/modbus/ModbusUrl.h"
#include "core/models/ModelledRuns.h"
#include "ui/models/LiveUpdatesModel.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/FitJob.h"
#include "ui/shell/SelectedCampaignLoader.h"
#include "ui/shell/Session.h"
#include "ui/widgets/LiveOffsetPlot.h"

namespace driftlab::ui {
namespace {

const QString kLiveEventSource = QStringLiteral("live");
const QString kBaseModel = QStringLiteral("heat-transfer");

/// driftlab_eoffset's Modbus port in resources/linuxcnc (docs/linuxcnc.md).
const QString kLinuxCncUrl = QStringLiteral("modbus://127.0.0.1:5020");

QString coloured(const QString& colour, const QString& text) {
    return QStringLiteral("<span style='color:%1'>%2</span>").arg(colour, text.toHtmlEscaped());
}

/// What the worker hands back to the GUI thread when it ends.
struct LiveOutcome {
    std::optional<live::LiveRunResult> result;
    QString error;
    bool badRequest = false;
    QString note;  ///< flagged samples left out
};

}  // namespace

LiveCompensationPage::LiveCompensationPage(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_model(new QComboBox(this)),
      m_run(new QComboBox(this)),
      m_train(new QListWidget(this)),
      m_interval(new QDoubleSpinBox(this)),
      m_maxChange(new QDoubleSpinBox(this)),
      m_points(new QSpinBox(this)),
      m_controller(new QComboBox(this)),
      m_url(new QLineEdit(this)),
      m_staleAfter(new QSpinBox(this)),
      m_speedup(new QDoubleSpinBox(this)),
      m_override(new QCheckBox(tr("Send even if worse than none (override)"), this)),
      m_start(new QPushButton(tr("Start"), this)),
      m_stop(new QPushButton(tr("Stop"), this)),
      m_harm(new QLabel(this)),
      m_gate(new QLabel(this)),
      m_status(new QLabel(this)),
      m_view(new QTableView(this)),
      m_updates(new LiveUpdatesModel(this)),
      m_plot(new LiveOffsetPlot(this)),
      m_loader(new SelectedCampaignLoader(session, false, this)),
      m_job(new BackgroundJob(this)) {
    // Live compensation steps the screw model online: heat-transfer, or an
    // extension of it the Diagnosis page adopted (docs/live-compensation.md).
    m_model->addItem(kBaseModel);
    m_model->setToolTip(
        tr("The screw model that runs online, fitted on the training runs: "
           "heat-transfer or an extension adopted on the Diagnosis page"));
    // An extension's name is long ("heat-transfer+motor_heat"): shown whole.
    m_model->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_model->setMinimumContentsLength(24);
    m_run->setToolTip(tr("The stored run replayed as live data (not a training run)"));
    m_run->setMinimumContentsLength(6);
    m_train->setToolTip(tr("The runs the model is fitted on"));
    m_train->setMaximumHeight(64);
    m_interval->setRange(1, 3600);
    m_interval->setDecimals(0);
    m_interval->setValue(60);
    m_interval->setSuffix(tr(" s"));
    m_maxChange->setRange(0.01, 1000);
    m_maxChange->setDecimals(2);
    m_maxChange->setValue(5);
    m_maxChange->setSuffix(tr(" µm"));
    m_maxChange->setToolTip(tr("The largest change of any value per update"));
    m_points->setRange(2, 1024);
    m_points->setValue(128);
    m_points->setToolTip(tr("Points of the live table over the run's measured targets"));
    m_controller->addItem(tr("None: rehearsal"), Rehearsal);
    m_controller->addItem(tr("LinuxCNC external offsets (driftlab_eoffset)"), LinuxCnc);
    m_controller->addItem(tr("Modbus live-offset registers (PLC)"), ModbusRegisters);
    // Its longest entry would widen every page's minimum: it grows with the window.
    m_controller->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_controller->setMinimumContentsLength(16);
    m_override->setToolTip(
        tr("Send a model that does worse than no compensation on its own "
           "cross-validation (the CLI's --force)"));
    m_url->setPlaceholderText(QStringLiteral("modbus://HOST:PORT"));
    m_staleAfter->setRange(1, 65535);
    m_staleAfter->setValue(600);
    m_staleAfter->setSuffix(tr(" s"));
    m_staleAfter->setToolTip(
        tr("The controller flags the offset stale after this long without an update"));
    m_speedup->setRange(0, 100000);
    m_speedup->setDecimals(0);
    m_speedup->setValue(0);
    m_speedup->setSpecialValueText(tr("as fast as possible"));
    m_speedup->setPrefix(tr("× "));
    m_speedup->setToolTip(tr("Replay this many times faster than the run was logged"));
    for (QLabel* label : {m_harm, m_gate, m_status}) {
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    m_harm->hide();
    m_view->setModel(m_updates);
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);

    auto* modelGroup = new QGroupBox(tr("Model and replay"), this);
    auto* modelForm = new QFormLayout(modelGroup);
    modelForm->addRow(tr("Model"), m_model);
    modelForm->addRow(tr("Training runs"), m_train);
    modelForm->addRow(tr("Replayed run"), m_run);
    auto* updateGroup = new QGroupBox(tr("Updates"), this);
    auto* updateForm = new QFormLayout(updateGroup);
    updateForm->addRow(tr("Interval"), m_interval);
    updateForm->addRow(tr("Change limit"), m_maxChange);
    updateForm->addRow(tr("Table points"), m_points);
    updateForm->addRow(tr("Pace"), m_speedup);
    auto* controllerGroup = new QGroupBox(tr("Controller"), this);
    auto* controllerForm = new QFormLayout(controllerGroup);
    controllerForm->addRow(tr("Send to"), m_controller);
    controllerForm->addRow(tr("Address"), m_url);
    controllerForm->addRow(tr("Live timeout"), m_staleAfter);
    controllerForm->addRow(m_override);
    auto* buttons = new QVBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    buttons->addStretch(1);
    auto* settings = new QHBoxLayout;
    settings->addWidget(modelGroup, 3);
    settings->addWidget(updateGroup, 2);
    settings->addWidget(controllerGroup, 3);
    settings->addLayout(buttons);

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_plot);
    split->addWidget(m_view);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setSizes({520, 500});

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(settings);
    layout->addWidget(m_harm);
    layout->addWidget(m_gate);
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    connect(m_start, &QPushButton::clicked, this, &LiveCompensationPage::start);
    connect(m_stop, &QPushButton::clicked, this, &LiveCompensationPage::stop);
    connect(m_run, &QComboBox::currentIndexChanged, this, &LiveCompensationPage::fillTrainRuns);
    connect(m_controller, &QComboBox::currentIndexChanged, this,
            &LiveCompensationPage::updateControllerFields);
    connect(m_job, &BackgroundJob::finished, this, &LiveCompensationPage::updateButtons);
    connect(m_loader, &SelectedCampaignLoader::cleared, this, &LiveCompensationPage::clearCampaign);
    connect(m_loader, &SelectedCampaignLoader::loadingStarted, this,
            [this] { m_status->setText(tr("loading the campaign…")); });
    connect(m_loader, &SelectedCampaignLoader::loaded, this, &LiveCompensationPage::onLoaded);
    updateControllerFields();
    m_loader->reload();
}

// The worker reports to this page: it is stopped and waited for first.
LiveCompensationPage::~LiveCompensationPage() {
    delete m_job;
}

bool LiveCompensationPage::isRunning() const {
    return m_job->isRunning();
}

void LiveCompensationPage::clearCampaign() {
    m_campaign.reset();
    m_run->clear();
    m_train->clear();
    m_status->setText(tr("Select a campaign with feed-axis runs in the campaign tree."));
    updateButtons();
}

void LiveCompensationPage::onLoaded(const LoadedCampaign& loaded) {
    if (!loaded.campaign) {
        m_campaign.reset();
        showError(tr("Loading the campaign: %1").arg(loaded.error));
        return updateButtons();
    }
    m_campaign = loaded.campaign;
    fillModels(loaded.adopted_extensions);
    const QString shown = m_run->currentText();
    const QStringList runs = models::modelledRuns(*m_campaign);
    {
        const QSignalBlocker blocker(m_run);
        m_run->clear();
        m_run->addItems(runs);
        // The last run by default: the first ones train the model.
        m_run->setCurrentIndex(runs.contains(shown) ? int(runs.indexOf(shown)) : runs.size() - 1);
    }
    fillTrainRuns();
    m_status->setText(runs.size() < 2
                          ? tr("Campaign %1 needs two feed-axis runs with positioning readings: "
                               "one to fit the model on, one to replay")
                                .arg(m_campaign->name)
                          : tr("Choose the training runs and the run to replay, then Start."));
    updateButtons();
    emit campaignShown();
}

void LiveCompensationPage::fillModels(const QStringList& extensions) {
    QStringList shown;
    for (int i = 0; i < m_model->count(); ++i) shown << m_model->itemText(i);
    const QString chosen = m_model->currentText();
    const QSignalBlocker blocker(m_model);
    m_model->clear();
    m_model->addItem(kBaseModel);
    m_model->addItems(extensions);
    // An extension adopted since the list was filled is the one to try; a
    // choice among the listed ones stays.
    const bool adopted = !extensions.isEmpty() && !shown.contains(extensions.front());
    const int keep = m_model->findText(chosen);
    m_model->setCurrentIndex(adopted ? 1 : std::max(keep, 0));
}

void LiveCompensationPage::fillTrainRuns() {
    if (!m_campaign) return;
    QStringList checked;
    for (int i = 0; i < m_train->count(); ++i)
        if (m_train->item(i)->checkState() == Qt::Checked) checked << m_train->item(i)->text();
    m_train->clear();
    for (const QString& id : models::modelledRuns(*m_campaign)) {
        if (id == m_run->currentText()) continue;  // a replayed run is never a training run
        auto* item = new QListWidgetItem(id, m_train);
        item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
        item->setCheckState(checked.isEmpty() || checked.contains(id) ? Qt::Checked
                                                                      : Qt::Unchecked);
    }
    updateButtons();
}

void LiveCompensationPage::updateControllerFields() {
    const auto kind = Controller(m_controller->currentData().toInt());
    m_url->setEnabled(kind != Rehearsal);
    m_staleAfter->setEnabled(kind != Rehearsal);
    m_override->setEnabled(kind != Rehearsal);
    if (kind == LinuxCnc && m_url->text().isEmpty()) m_url->setText(kLinuxCncUrl);
    if (kind == ModbusRegisters && m_url->text().isEmpty())
        m_url->setText(m_session.runSetup().controller_url);
}

void LiveCompensationPage::updateButtons() {
    const bool running = m_job->isRunning();
    m_start->setEnabled(!running && m_campaign && m_run->count() > 0 && m_train->count() > 0);
    m_stop->setEnabled(running);
}

live::LiveCompensationOptions LiveCompensationPage::options(QString* error) const {
    live::LiveCompensationOptions o;
    o.model = m_model->currentText();
    o.run = m_run->currentText();
    for (int i = 0; i < m_train->count(); ++i)
        if (m_train->item(i)->checkState() == Qt::Checked) o.train_runs << m_train->item(i)->text();
    if (o.train_runs.isEmpty()) *error = tr("Tick at least one training run.");
    o.update_interval_s = m_interval->value();
    o.max_change_um = m_maxChange->value();
    o.table_points = m_points->value();
    o.speedup = m_speedup->value();
    if (Controller(m_controller->currentData().toInt()) != Rehearsal) {
        QString why;
        o.controller = modbus::parseModbusUrl(m_url->text().trimmed(), &why);
        if (!o.controller) *error = tr("Controller address: %1").arg(why);
        o.stale_after_s = m_staleAfter->value();
        o.override_no_harm = m_override->isChecked();
    }
    return o;
}

void LiveCompensationPage::start() {
    if (m_job->isRunning() || !m_campaign || !m_session.campaignId()) return;
    QString error;
    live::LiveCompensationOptions o = options(&error);
    if (!error.isEmpty()) return showError(error);
    m_updates->reset(NAN);
    m_plot->clear();
    m_harm->hide();
    m_gate->clear();
    m_cutSince_s.reset();
    m_lastTime_s = 0;
    m_status->setText(
        tr("fitting the %1 model on %2…").arg(o.model, o.train_runs.join(QStringLiteral(", "))));
    // Reports cross to the GUI thread as queued calls: in order, before the job's end.
    o.on_update = [this](const compensation::LiveUpdate& u) {
        QMetaObject::invokeMethod(
            this, [this, u] { showUpdate(u); }, Qt::QueuedConnection);
    };
    o.on_state = [this](double t_s, MachineState state) {
        QMetaObject::invokeMethod(
            this, [this, t_s, state] { showState(t_s, state); }, Qt::QueuedConnection);
    };
    const QString store = m_session.storePath();
    const qint64 campaignId = *m_session.campaignId();
    auto outcome = std::make_shared<LiveOutcome>();
    m_job->start(
        [this, o, store, campaignId, outcome](JobControl& control) mutable {
            o.cancelled = [&control] { return control.cancelled(); };
            o.progress = [&control](const QString&, double fraction) {
                control.progress(fraction);
            };
            try {
                const auto campaign =
                    loadCampaignForModels(store, campaignId, &outcome->note, &outcome->error);
                if (!campaign) return;
                const live::LivePlan plan = live::planLive(*campaign, o);
                QMetaObject::invokeMethod(
                    this, [this, plan] { showPlan(plan); }, Qt::QueuedConnection);
                outcome->result = live::runLive(plan, o);
            } catch (const ServiceError& e) {
                outcome->error = e.message();
                outcome->badRequest = e.kind == ServiceError::Kind::BadRequest;
            }
        },
        [this, outcome, o] {
            if (m_cutSince_s) m_plot->addCut(*m_cutSince_s, m_lastTime_s);
            m_plot->show(m_updates->updates(), m_updates->uncertaintyUm());
            if (!outcome->result) {
                showError(outcome->error);
            } else if (!outcome->result->controller_error.isEmpty()) {
                showError(tr("The controller stopped answering after %1 updates written: %2")
                              .arg(outcome->result->written)
                              .arg(outcome->result->controller_error));
            } else {
                const live::LiveRunResult& r = *outcome->result;
                const compensation::LiveReplayResult& replay = r.replay;
                m_status->setText(
                    tr("%1%2 updates%3; on %4's %5 readings the thermal error goes from %6 to "
                       "%7 µm RMS with the live table (%8 %), to %9 µm RMS with the single "
                       "offset%10")
                        .arg(replay.cancelled ? tr("Stopped after ") : QString())
                        .arg(replay.updates.size())
                        .arg(r.controller.isEmpty() ? QString()
                                                    : tr(" sent to %1").arg(r.controller))
                        .arg(o.run)
                        .arg(replay.readings)
                        .arg(replay.rms_before_um, 0, 'f', 2)
                        .arg(replay.rms_after_um, 0, 'f', 2)
                        .arg(100 * r.reduction(), 0, 'f', 0)
                        .arg(replay.rms_after_offset_um, 0, 'f', 2)
                        .arg(outcome->note.isEmpty() ? QString()
                                                     : QStringLiteral(" (%1)").arg(outcome->note)));
                emit m_session.event(QStringLiteral("info"), kLiveEventSource, m_status->text());
            }
            updateButtons();
            emit runFinished();
        });
    updateButtons();
}

void LiveCompensationPage::stop() {
    m_job->cancel();
}

void LiveCompensationPage::showPlan(const live::LivePlan& plan) {
    m_updates->reset(plan.uncertainty_um);
    m_status->setText(tr("replaying %1 through %2, offset at %3 mm…")
                          .arg(plan.run, plan.model())
                          .arg(plan.settings.offset_position_mm, 0, 'f', 1));
    const QString harm = plan.harmReason();
    if (harm.isEmpty()) return;
    // No harm: shown whether or not it stops the run, so the user knows.
    const bool toController = Controller(m_controller->currentData().toInt()) != Rehearsal;
    if (!toController)
        m_harm->setText(coloured(QStringLiteral("#a05000"),
                                 tr("%1. A rehearsal shows it; sending it to a controller is "
                                    "refused without the override.")
                                     .arg(harm)));
    else if (m_override->isChecked())
        m_harm->setText(
            coloured(QStringLiteral("#a05000"), tr("%1. Sent anyway: override ticked.").arg(harm)));
    else
        m_harm->setText(QStringLiteral("<b>%1</b>")
                            .arg(coloured(QStringLiteral("#b00000"),
                                          tr("Refused: %1. Nothing was sent; tick the override "
                                             "to send it anyway.")
                                              .arg(harm))));
    m_harm->show();
}

void LiveCompensationPage::showState(double time_s, MachineState state) {
    m_lastTime_s = std::max(m_lastTime_s, time_s);
    const bool cutting = !isSafeToCompensate(state);
    if (cutting && !m_cutSince_s) m_cutSince_s = time_s;
    if (!cutting && m_cutSince_s) {
        m_plot->addCut(*m_cutSince_s, time_s);
        m_cutSince_s.reset();
    }
    m_gate->setText(cutting ? tr("Cut gate at %1 s: cutting, updates held until the cut ends")
                                  .arg(time_s, 0, 'f', 0)
                            : tr("Cut gate at %1 s: %2, updates applied")
                                  .arg(time_s, 0, 'f', 0)
                                  .arg(machineStateName(state)));
}

void LiveCompensationPage::showUpdate(const compensation::LiveUpdate& update) {
    m_lastTime_s = std::max(m_lastTime_s, update.time_s);
    m_updates->append(update);
    m_plot->show(m_updates->updates(), m_updates->uncertaintyUm());
    m_view->scrollToBottom();
    emit updateShown();
}

void LiveCompensationPage::showError(const QString& message) {
    m_status->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), kLiveEventSource, message);
}

}  // namespace driftlab::ui
