#pragma once
// The machine history of the selected campaign's machine axis (docs/history.md):
// the table of its campaigns and the trend of A, E, R, B, M against the date.
// The store is read on a worker thread with its own read-only connection.

#include <QFutureWatcher>
#include <QString>
#include <QWidget>
#include <optional>

#include "core/history/MachineHistory.h"

class QLabel;
class QTableView;

namespace driftlab::ui {

class MachineHistoryModel;
class PlotView;

class MachineHistoryView : public QWidget {
    Q_OBJECT
public:
    explicit MachineHistoryView(QWidget* parent = nullptr);
    ~MachineHistoryView() override;

    /// Loads the history of `machine` and `axis` from the store at `storePath`.
    void load(const QString& storePath, const QString& machine, const QString& axis);
    void clear();

    MachineHistoryModel* model() const { return m_model; }
    QLabel* messageLabel() const { return m_message; }
    PlotView* plot() const { return m_plot; }

signals:
    /// The history is shown (or why not, in the message).
    void loaded();

private:
    struct Result {
        std::optional<history::MachineHistory> history;
        QString error;
    };
    void show(const Result& result);

    QLabel* m_message;
    QTableView* m_view;
    MachineHistoryModel* m_model;
    PlotView* m_plot;
    QFutureWatcher<Result> m_watcher;
};

}  // namespace driftlab::ui
