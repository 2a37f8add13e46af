#pragma once
// The controller side of the Compensation page: the controller's Modbus URL
// (remembered in QSettings), "Read controller" (its active table, for the
// difference), "Push…" (read the active table, confirm what changes, push with
// the steps shown, record the outcome in the store's push history) and the
// campaign's push history. Every Modbus exchange runs on a worker thread.

#include <QFutureWatcher>
#include <QWidget>
#include <atomic>
#include <optional>

#include "acquisition/push/ActiveTableRead.h"
#include "acquisition/push/PushResult.h"
#include "core/compensation/CompensationTable.h"
#include "db/PushHistory.h"

class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableView;

namespace driftlab::ui {

class PushConfirmDialog;
class PushHistoryModel;
class Session;

class ControllerPanel : public QWidget {
    Q_OBJECT
public:
    static constexpr const char* kUrlSetting = "compensation/controller_url";

    ControllerPanel(Session& session, QWidget* parent = nullptr);
    ~ControllerPanel() override;

    /// The table a push sends and the run it was made from (empty: none).
    void setTable(const std::optional<compensation::CompensationTable>& table, const QString& run);
    void setHistory(std::vector<db::PushRecord> pushes);

    QLineEdit* urlEdit() const { return m_url; }
    QPushButton* readButton() const { return m_read; }
    QPushButton* pushButton() const { return m_push; }
    QPushButton* cancelButton() const { return m_cancel; }
    QLabel* statusLabel() const { return m_status; }
    QListWidget* stepList() const { return m_steps; }
    PushHistoryModel* historyModel() const { return m_history; }
    /// The confirmation on screen, if any.
    PushConfirmDialog* confirmation() const { return m_confirm; }

signals:
    /// The controller's active table, read by "Read controller" or before a push.
    void activeTableRead(const push::TableImage& image);
    void pushFinished(const push::PushResult& result);
    /// A read or a push is under way (the page disables its own controls).
    void busyChanged(bool busy);

private:
    struct PushDone {
        push::PushResult result;
        QString record_error;  ///< empty when recorded
        std::vector<db::PushRecord> pushes;
    };

    void readController(bool thenConfirm);
    void onRead(bool thenConfirm);
    void startPush();
    void onPushed();
    std::optional<modbus::ModbusUrl> url();
    void setBusy(bool busy);
    void fail(const QString& message);

    Session& m_session;
    QLineEdit* m_url;
    QPushButton* m_read;
    QPushButton* m_push;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    QListWidget* m_steps;
    QTableView* m_historyView;
    PushHistoryModel* m_history;
    PushConfirmDialog* m_confirm = nullptr;

    std::optional<compensation::CompensationTable> m_table;
    QString m_run;
    std::optional<modbus::ModbusUrl> m_target;
    QFutureWatcher<push::ActiveTable> m_reading;
    QFutureWatcher<PushDone> m_pushing;
    std::atomic_bool m_cancelRequested{false};
};

}  // namespace driftlab::ui
