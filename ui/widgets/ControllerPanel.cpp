#include "ui/widgets/ControllerPanel.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "acquisition/push/PushRecording.h"
#include "acquisition/push/TablePush.h"
#include "ui/models/PushHistoryModel.h"
#include "ui/shell/Session.h"
#include "ui/widgets/CampaignLoad.h"
#include "ui/widgets/PushConfirmDialog.h"

namespace driftlab::ui {
namespace {

const QString kSource = QStringLiteral("compensation");

}  // namespace

ControllerPanel::ControllerPanel(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_url(new QLineEdit(this)),
      m_read(new QPushButton(tr("Read controller"), this)),
      m_push(new QPushButton(tr("Push…"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)),
      m_progress(new QProgressBar(this)),
      m_status(new QLabel(this)),
      m_steps(new QListWidget(this)),
      m_historyView(new QTableView(this)),
      m_history(new PushHistoryModel(this)) {
    m_url->setText(QSettings()
                       .value(QLatin1String(kUrlSetting), QStringLiteral("modbus://127.0.0.1:1502"))
                       .toString());
    m_url->setToolTip(tr("The controller's Modbus TCP address (docs/modbus-register-map.md)"));
    m_read->setToolTip(tr("Read the table the controller applies now and show the difference"));
    m_push->setToolTip(
        tr("Send the table: staged, checksummed, applied when the machine is not "
           "cutting, read back, rolled back on any mismatch"));
    m_cancel->setEnabled(false);
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    m_progress->setMaximumHeight(16);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_steps->setMaximumHeight(64);
    m_steps->hide();  // shown while and after a push: the history gets the room otherwise
    m_historyView->setModel(m_history);
    m_historyView->verticalHeader()->hide();
    m_historyView->horizontalHeader()->setStretchLastSection(true);
    m_historyView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_historyView->setEditTriggers(QAbstractItemView::NoEditTriggers);

    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Controller"), this));
    row->addWidget(m_url, 1);
    row->addWidget(m_read);
    row->addWidget(m_push);
    row->addWidget(m_cancel);
    auto* history = new QGroupBox(tr("Push history of the campaign"), this);
    auto* historyLayout = new QVBoxLayout(history);
    historyLayout->setContentsMargins(4, 4, 4, 4);
    historyLayout->addWidget(m_historyView);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(row);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_steps);
    layout->addWidget(history, 1);

    connect(m_read, &QPushButton::clicked, this, [this] { readController(false); });
    connect(m_push, &QPushButton::clicked, this, [this] { readController(true); });
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        m_cancelRequested = true;
        m_status->setText(tr("cancelling… (the controller is brought back to its table)"));
    });
    connect(&m_reading, &QFutureWatcher<push::ActiveTable>::finished, this,
            [this] { onRead(m_reading.property("confirm").toBool()); });
    connect(&m_pushing, &QFutureWatcher<PushDone>::finished, this, &ControllerPanel::onPushed);
    setTable(std::nullopt, {});
}

ControllerPanel::~ControllerPanel() {
    // A push in flight ends within its own timeouts; cancelling shortens it.
    m_cancelRequested = true;
    m_reading.waitForFinished();
    m_pushing.waitForFinished();
}

void ControllerPanel::setTable(const std::optional<compensation::CompensationTable>& table,
                               const QString& run) {
    m_table = table;
    m_run = run;
    const bool idle = !m_reading.isRunning() && !m_pushing.isRunning();
    m_push->setEnabled(idle && m_table.has_value());
}

void ControllerPanel::setHistory(std::vector<db::PushRecord> pushes) {
    m_history->setPushes(std::move(pushes));
    m_historyView->resizeColumnsToContents();
}

std::optional<modbus::ModbusUrl> ControllerPanel::url() {
    QString error;
    auto parsed = modbus::parseModbusUrl(m_url->text().trimmed(), &error);
    if (!parsed) {
        fail(tr("Controller address: %1").arg(error));
        return std::nullopt;
    }
    QSettings().setValue(QLatin1String(kUrlSetting), m_url->text().trimmed());
    return parsed;
}

void ControllerPanel::setBusy(bool busy) {
    m_read->setEnabled(!busy);
    m_push->setEnabled(!busy && m_table.has_value());
    m_url->setEnabled(!busy);
    m_cancel->setEnabled(busy && m_pushing.isRunning());
    emit busyChanged(busy);
}

void ControllerPanel::fail(const QString& message) {
    m_status->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), kSource, message);
}

void ControllerPanel::readController(bool thenConfirm) {
    if (m_reading.isRunning() || m_pushing.isRunning()) return;
    if (thenConfirm && !m_table) return fail(tr("Push: there is no table to push"));
    m_target = url();
    if (!m_target) return;
    m_steps->clear();
    m_steps->hide();
    m_progress->setValue(0);
    m_status->setText(tr("reading the active table of %1…").arg(m_target->toString()));
    setBusy(true);
    m_reading.setProperty("confirm", thenConfirm);
    m_reading.setFuture(
        QtConcurrent::run([url = *m_target] { return push::readActiveTable(url); }));
}

void ControllerPanel::onRead(bool thenConfirm) {
    const push::ActiveTable active = m_reading.result();
    setBusy(false);
    if (!active.ok()) return fail(tr("Read controller: %1").arg(active.error));
    emit activeTableRead(active.image);
    const QString holds =
        active.empty()
            ? tr("no table")
            : tr("table v%1 (%2 points)").arg(active.image.version()).arg(active.image.points());
    m_status->setText(tr("%1 holds %2 (machine %3)")
                          .arg(active.controller, holds, machineStateName(active.state)));
    if (!thenConfirm || !m_table) return;
    const push::TableChange change = push::changeAgainst(active.image, *m_table);
    m_confirm = new PushConfirmDialog(active, *m_table, change, this);
    connect(m_confirm, &QDialog::accepted, this, &ControllerPanel::startPush);
    connect(m_confirm, &QDialog::rejected, this,
            [this] { m_status->setText(tr("push not sent: cancelled at the confirmation")); });
    connect(m_confirm, &QObject::destroyed, this, [this] { m_confirm = nullptr; });
    m_confirm->open();
}

void ControllerPanel::startPush() {
    if (!m_table || !m_target || m_pushing.isRunning()) return;
    m_cancelRequested = false;
    m_steps->clear();
    m_status->setText(tr("pushing to %1…").arg(m_target->toString()));
    push::PushOptions options;
    options.cancel = &m_cancelRequested;
    // Called on the worker: the GUI hears of each step through the event loop.
    options.progress = [this](double fraction, const QString& step) {
        QMetaObject::invokeMethod(
            this,
            [this, fraction, step] {
                m_progress->setValue(int(fraction * 100));
                m_steps->addItem(step);
                m_steps->show();
                m_steps->scrollToBottom();
            },
            Qt::QueuedConnection);
        return true;
    };
    const std::optional<qint64> campaignId = m_session.campaignId();
    const QString storePath = m_session.storePath();
    m_pushing.setFuture(QtConcurrent::run(
        [url = *m_target, table = *m_table, run = m_run, campaignId, storePath, options] {
            PushDone done;
            done.result = push::pushTable(url, table, options);
            const db::PushRecord record = push::pushRecord(table, campaignId, run, done.result);
            if (!push::recordPush(storePath, record, &done.record_error)) return done;
            if (campaignId) done.pushes = campaignPushes(storePath, *campaignId);
            return done;
        }));
    setBusy(true);
}

void ControllerPanel::onPushed() {
    const PushDone done = m_pushing.result();
    setBusy(false);
    const push::PushResult& r = done.result;
    m_steps->clear();
    for (const push::PushStep& step : r.steps) {
        auto* item = new QListWidgetItem(
            QStringLiteral("%1 %2 — %3")
                .arg(step.ok ? QStringLiteral("✔") : QStringLiteral("✘"), step.name, step.detail),
            m_steps);
        item->setForeground(step.ok ? QColor(0x20, 0x70, 0x20) : QColor(0xb0, 0x00, 0x00));
    }
    m_steps->setVisible(m_steps->count() > 0);
    const QString outcome = push::outcomeName(r.outcome);
    if (r.ok()) {
        m_progress->setValue(100);
        m_status->setText(QStringLiteral("<b style='color:#207020'>%1</b>: %2")
                              .arg(outcome, r.message.toHtmlEscaped()));
        emit m_session.event(QStringLiteral("info"), kSource,
                             QStringLiteral("push %1: %2").arg(outcome, r.message));
    } else {
        fail(QStringLiteral("push %1: %2").arg(outcome, r.message));
    }
    if (!done.record_error.isEmpty())
        fail(tr("push %1, but not recorded in the push history: %2")
                 .arg(outcome, done.record_error));
    else
        setHistory(done.pushes);
    emit pushFinished(r);
    m_session.notifyStoreChanged();
}

}  // namespace driftlab::ui
