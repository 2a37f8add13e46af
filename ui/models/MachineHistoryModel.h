#pragma once
// The machine history table of the ISO 230-2 page (docs/history.md): one row
// per campaign of the machine axis, oldest first, with A, E, R, B, M, the
// change of A from the first campaign and the ISO 230-3 drift. Display text
// has 3 decimals (µm) and "n/a" for what was not determined; Qt::UserRole
// gives the number (NaN when not determined), the date as a QDateTime.

#include <QAbstractTableModel>

#include "core/history/MachineHistory.h"

namespace driftlab::ui {

class MachineHistoryModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Date, Campaign, Run, A, E, R, B, M, AChangeFromFirst, MaxDrift, Stabilised };

    explicit MachineHistoryModel(QObject* parent = nullptr);

    void setHistory(history::MachineHistory history);
    const history::MachineHistory& history() const { return m_history; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    double value(std::size_t row, int column) const;
    history::MachineHistory m_history;
};

}  // namespace driftlab::ui
