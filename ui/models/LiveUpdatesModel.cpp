#include "ui/models/LiveUpdatesModel.h"

#include <QBrush>
#include <QColor>
#include <cmath>

namespace driftlab::ui {
namespace {

/// An update applied later than due waited for a cut to end.
bool waitedForCut(const compensation::LiveUpdate& u) {
    return u.time_s > u.due_s + 1e-9;
}

}  // namespace

LiveUpdatesModel::LiveUpdatesModel(QObject* parent) : QAbstractTableModel(parent) {}

void LiveUpdatesModel::reset(double uncertainty_um) {
    beginResetModel();
    m_updates.clear();
    m_uncertainty_um = uncertainty_um;
    endResetModel();
}

void LiveUpdatesModel::append(const compensation::LiveUpdate& update) {
    const int row = int(m_updates.size());
    beginInsertRows({}, row, row);
    m_updates.push_back(update);
    endInsertRows();
}

int LiveUpdatesModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_updates.size());
}

int LiveUpdatesModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LiveUpdatesModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const compensation::LiveUpdate& u = m_updates[std::size_t(index.row())];
    if (role == Qt::TextAlignmentRole)
        return index.column() == Note ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                      : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && index.column() == HeldBack && u.limited)
        return QBrush(QColor(0xa0, 0x50, 0x00));
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    const bool edit = role == Qt::EditRole;  // the raw number, for tests and copying
    const auto number = [edit](double value, int decimals) -> QVariant {
        if (edit) return value;
        return std::isfinite(value) ? QString::number(value, 'f', decimals) : QStringLiteral("n/a");
    };
    switch (Column(index.column())) {
        case Time:
            return number(u.time_s, 0);
        case Due:
            return number(u.due_s, 0);
        case Offset:
            return number(u.offset_um, 3);
        case Prediction:
            // With its 95 % half-width, the same for every update of a run.
            if (edit || !std::isfinite(m_uncertainty_um)) return number(u.target_offset_um, 3);
            return QStringLiteral("%1 ± %2")
                .arg(u.target_offset_um, 0, 'f', 3)
                .arg(m_uncertainty_um, 0, 'f', 2);
        case HeldBack:
            return number(u.target_offset_um - u.offset_um, 3);
        case Note: {
            QStringList notes;
            if (waitedForCut(u))
                notes << tr("waited %1 s for the cut").arg(u.time_s - u.due_s, 0, 'f', 0);
            if (u.limited) notes << tr("change limited");
            return notes.join(QStringLiteral("; "));
        }
        case ColumnCount:
            break;
    }
    return {};
}

QVariant LiveUpdatesModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (Column(section)) {
        case Time:
            return tr("Applied (s)");
        case Due:
            return tr("Due (s)");
        case Offset:
            return tr("Sent (µm)");
        case Prediction:
            return tr("Model ± 95 % (µm)");
        case HeldBack:
            return tr("Held back (µm)");
        case Note:
            return tr("Note");
        case ColumnCount:
            break;
    }
    return {};
}

}  // namespace driftlab::ui
