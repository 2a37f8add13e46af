#pragma once
// Set-up section "Channels": the channel table (ChannelSetupModel) with
// combo-box editors for quantity and role, add and remove buttons, and the
// problems of the table under it.

#include <QWidget>

class QLabel;
class QTableView;

namespace driftlab::ui {

class ChannelSetupModel;

class ChannelTable : public QWidget {
    Q_OBJECT
public:
    explicit ChannelTable(ChannelSetupModel& model, QWidget* parent = nullptr);

    QTableView* view() const { return m_view; }
    /// Shows the table's problems under it (empty: none).
    void showProblems(const QStringList& problems);

private:
    ChannelSetupModel& m_model;
    QTableView* m_view;
    QLabel* m_problems;
};

}  // namespace driftlab::ui
