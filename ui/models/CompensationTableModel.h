#pragma once
// The Compensation page's table: one row per point, with the position, the
// corrections (µm, what the controller adds to the command) and their expanded
// uncertainty (95 %), and, once the
// controller's active table was read, its corrections at the same points and
// the change the new table makes. Display text is formatted as the CSV export
// writes it (position 4 decimals, corrections 3); Qt::UserRole gives the number.

#include <QAbstractTableModel>
#include <optional>

#include "acquisition/push/ActiveTableRead.h"
#include "core/compensation/CompensationTable.h"

namespace driftlab::ui {

class CompensationTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Position,
        CorrectionPlus,
        CorrectionMinus,
        Uncertainty,
        ActivePlus,
        ActiveMinus,
        ChangePlus,
        ChangeMinus,
    };

    explicit CompensationTableModel(QObject* parent = nullptr);

    /// A new table; the difference is dropped until setActive() again.
    void setTable(const compensation::CompensationTable& table);
    /// The controller's active table: adds its columns and the change.
    void setActive(const push::TableImage& active);
    void clear();

    const compensation::CompensationTable& table() const { return m_table; }
    const std::optional<push::TableChange>& change() const { return m_change; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    double value(int row, int column) const;

    compensation::CompensationTable m_table;
    std::optional<push::TableImage> m_active;
    std::optional<push::TableChange> m_change;
};

}  // namespace driftlab::ui
