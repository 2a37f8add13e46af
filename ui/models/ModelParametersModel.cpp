#include "ui/models/ModelParametersModel.h"

#include <cmath>

namespace driftlab::ui {

ModelParametersModel::ModelParametersModel(QObject* parent) : QAbstractTableModel(parent) {}

void ModelParametersModel::setParameters(const std::map<QString, models::Parameter>& parameters) {
    beginResetModel();
    m_rows.assign(parameters.begin(), parameters.end());
    endResetModel();
}

int ModelParametersModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int ModelParametersModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ModelParametersModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const auto& [name, p] = m_rows[std::size_t(index.row())];
    if (role == Qt::TextAlignmentRole && (index.column() == Value || index.column() == Sigma))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && index.column() == Sigma && !std::isfinite(p.sigma))
        return tr("the training runs do not determine this parameter");
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Name:
            return name;
        case Value:
            return QString::number(p.value, 'g', 5);
        case Sigma:
            return std::isfinite(p.sigma) ? QString::number(p.sigma, 'g', 2) : QStringLiteral("—");
        case Unit:
            return p.unit;
        default:
            return {};
    }
}

QVariant ModelParametersModel::headerData(int section, Qt::Orientation orientation,
                                          int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Name:
            return tr("Parameter");
        case Value:
            return tr("Value");
        case Sigma:
            return tr("σ (1σ)");
        case Unit:
            return tr("Unit");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
