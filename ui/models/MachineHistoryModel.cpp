#include "ui/models/MachineHistoryModel.h"

#include <cmath>

namespace driftlab::ui {

MachineHistoryModel::MachineHistoryModel(QObject* parent) : QAbstractTableModel(parent) {}

void MachineHistoryModel::setHistory(history::MachineHistory history) {
    beginResetModel();
    m_history = std::move(history);
    endResetModel();
}

int MachineHistoryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_history.entries.size());
}

int MachineHistoryModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : Stabilised + 1;
}

double MachineHistoryModel::value(std::size_t row, int column) const {
    const history::HistoryEntry& e = m_history.entries[row];
    switch (column) {
        case A:
            return e.positioning.value_um(history::Figure::A);
        case E:
            return e.positioning.value_um(history::Figure::E);
        case R:
            return e.positioning.value_um(history::Figure::R);
        case B:
            return e.positioning.value_um(history::Figure::B);
        case M:
            return e.positioning.value_um(history::Figure::M);
        case AChangeFromFirst:
            return m_history.changeFromFirst_um(row, history::Figure::A);
        case MaxDrift:
            return e.drift.determined() ? e.drift.max_drift_um : iso::kNotDetermined;
        case Stabilised:
            return e.drift.determined() ? e.drift.stabilised_time_s : iso::kNotDetermined;
        default:
            return iso::kNotDetermined;
    }
}

QVariant MachineHistoryModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const std::size_t row = std::size_t(index.row());
    const history::HistoryEntry& e = m_history.entries[row];
    const int column = index.column();
    if (column == Date) {
        if (role == Qt::DisplayRole) return e.date.utc.toString(QStringLiteral("yyyy-MM-dd"));
        if (role == Qt::UserRole) return e.date.utc;
        if (role == Qt::ToolTipRole)
            return tr("%1 (%2)").arg(e.date.utc.toString(Qt::ISODate), e.date.source);
        return {};
    }
    if (column == Campaign) {
        if (role == Qt::DisplayRole) return tr("%1 %2").arg(e.campaign_id).arg(e.campaign);
        if (role == Qt::UserRole) return e.campaign_id;
        return {};
    }
    if (column == Run) {
        if (role == Qt::DisplayRole) return e.positioning.run_id;
        if (role == Qt::ToolTipRole)
            return e.positioning.not_determined.isEmpty() ? e.positioning.run_note
                                                          : e.positioning.not_determined;
        return {};
    }
    const double v = value(row, column);
    switch (role) {
        case Qt::DisplayRole:
            if (column == Stabilised)
                return std::isfinite(v) ? QString::number(v, 'f', 0) : tr("n/a");
            return std::isfinite(v) ? QString::number(v, 'f', 3) : tr("n/a");
        case Qt::UserRole:
            return v;
        case Qt::TextAlignmentRole:
            return int(Qt::AlignRight | Qt::AlignVCenter);
        default:
            return {};
    }
}

QVariant MachineHistoryModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    if (role != Qt::DisplayRole) return {};
    switch (section) {
        case Date:
            return tr("Date");
        case Campaign:
            return tr("Campaign");
        case Run:
            return tr("Run");
        case A:
            return tr("A µm");
        case E:
            return tr("E µm");
        case R:
            return tr("R µm");
        case B:
            return tr("B µm");
        case M:
            return tr("M µm");
        case AChangeFromFirst:
            return tr("ΔA first µm");
        case MaxDrift:
            return tr("Max drift µm");
        case Stabilised:
            return tr("Stabilised s");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
