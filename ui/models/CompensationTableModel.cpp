#include "ui/models/CompensationTableModel.h"

#include <QBrush>
#include <QColor>
#include <cmath>

#include "core/compensation/ExportResult.h"

namespace driftlab::ui {

CompensationTableModel::CompensationTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void CompensationTableModel::setTable(const compensation::CompensationTable& table) {
    beginResetModel();
    m_table = table;
    m_change.reset();
    if (m_active && m_table.size() > 0) m_change = push::changeAgainst(*m_active, m_table);
    endResetModel();
}

void CompensationTableModel::setActive(const push::TableImage& active) {
    beginResetModel();
    m_active = active;
    m_change.reset();
    if (m_table.size() > 0) m_change = push::changeAgainst(active, m_table);
    endResetModel();
}

void CompensationTableModel::clear() {
    beginResetModel();
    m_table = {};
    m_active.reset();
    m_change.reset();
    endResetModel();
}

int CompensationTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_table.size());
}

int CompensationTableModel::columnCount(const QModelIndex& parent) const {
    if (parent.isValid()) return 0;
    return m_change ? ChangeMinus + 1 : Uncertainty + 1;
}

double CompensationTableModel::value(int row, int column) const {
    const auto i = std::size_t(row);
    switch (column) {
        case Position:
            return m_table.position_mm[i];
        case CorrectionPlus:
            return m_table.correction_plus_um[i];
        case CorrectionMinus:
            return m_table.correction_minus_um[i];
        case Uncertainty:
            return i < m_table.uncertainty_um.size() ? m_table.uncertainty_um[i] : std::nan("");
        case ActivePlus:
            return m_change->active.correction_plus_um[i];
        case ActiveMinus:
            return m_change->active.correction_minus_um[i];
        case ChangePlus:
            return m_change->change_plus_um[i];
        default:
            return m_change->change_minus_um[i];
    }
}

QVariant CompensationTableModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const double v = value(index.row(), index.column());
    switch (role) {
        case Qt::DisplayRole:
            return QString::fromLatin1(compensation::fixed(v, index.column() == Position ? 4 : 3));
        case Qt::UserRole:
            return v;
        case Qt::TextAlignmentRole:
            return int(Qt::AlignRight | Qt::AlignVCenter);
        case Qt::ForegroundRole:
            // A point the push would change stands out against the unchanged ones.
            if ((index.column() == ChangePlus || index.column() == ChangeMinus) &&
                std::abs(v) >= 0.05)
                return QBrush(QColor(0xb0, 0x40, 0x00));
            return {};
        default:
            return {};
    }
}

QVariant CompensationTableModel::headerData(int section, Qt::Orientation orientation,
                                            int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    switch (section) {
        case Position:
            return tr("Position\nmm");
        case CorrectionPlus:
            return tr("Correction\n+ µm");
        case CorrectionMinus:
            return tr("Correction\n− µm");
        case Uncertainty:
            return tr("Uncertainty\n95 % ± µm");
        case ActivePlus:
            return tr("Active\n+ µm");
        case ActiveMinus:
            return tr("Active\n− µm");
        case ChangePlus:
            return tr("Change\n+ µm");
        case ChangeMinus:
            return tr("Change\n− µm");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
