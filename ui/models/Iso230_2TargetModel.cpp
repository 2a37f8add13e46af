#include "ui/models/Iso230_2TargetModel.h"

#include <cmath>

namespace driftlab::ui {

Iso230_2TargetModel::Iso230_2TargetModel(QObject* parent) : QAbstractTableModel(parent) {}

void Iso230_2TargetModel::setTargets(std::vector<iso::TargetResult> targets) {
    beginResetModel();
    m_targets = std::move(targets);
    endResetModel();
}

int Iso230_2TargetModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_targets.size());
}

int Iso230_2TargetModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : R + 1;
}

double Iso230_2TargetModel::value(const iso::TargetResult& t, int column) const {
    switch (column) {
        case Target:
            return t.target_mm;
        case CountUp:
            return t.n_up;
        case CountDown:
            return t.n_down;
        case MeanUp:
            return t.mean_up_um;
        case MeanDown:
            return t.mean_down_um;
        case Mean:
            return t.mean_um;
        case SUp:
            return t.s_up_um;
        case SDown:
            return t.s_down_um;
        case Reversal:
            return t.reversal_um;
        case RUp:
            return t.r_up_um;
        case RDown:
            return t.r_down_um;
        default:
            return t.r_um;
    }
}

QVariant Iso230_2TargetModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const double v = value(m_targets[std::size_t(index.row())], index.column());
    switch (role) {
        case Qt::DisplayRole:
            if (index.column() == CountUp || index.column() == CountDown) return int(v);
            return std::isfinite(v) ? QString::number(v, 'f', 3) : tr("n/a");
        case Qt::UserRole:
            return v;
        case Qt::TextAlignmentRole:
            return int(Qt::AlignRight | Qt::AlignVCenter);
        default:
            return {};
    }
}

QVariant Iso230_2TargetModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical)
        return role == Qt::DisplayRole ? QVariant(section + 1) : QVariant();
    if (role == Qt::ToolTipRole) {
        switch (section) {
            case MeanUp:
                return tr("mean positional deviation, positive approach (µm)");
            case MeanDown:
                return tr("mean positional deviation, negative approach (µm)");
            case Reversal:
                return tr("reversal value B_i = x̄↑_i − x̄↓_i (µm)");
            case R:
                return tr("bidirectional repeatability at the target (µm)");
            default:
                return {};
        }
    }
    if (role != Qt::DisplayRole) return {};
    switch (section) {
        case Target:
            return tr("Target mm");
        case CountUp:
            return tr("n↑");
        case CountDown:
            return tr("n↓");
        case MeanUp:
            return tr("x̄↑ µm");
        case MeanDown:
            return tr("x̄↓ µm");
        case Mean:
            return tr("x̄ µm");
        case SUp:
            return tr("s↑ µm");
        case SDown:
            return tr("s↓ µm");
        case Reversal:
            return tr("B_i µm");
        case RUp:
            return tr("R↑_i µm");
        case RDown:
            return tr("R↓_i µm");
        case R:
            return tr("R_i µm");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
