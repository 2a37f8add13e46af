#include "ui/models/TestScoresModel.h"

#include <cmath>

namespace driftlab::ui {
namespace {

QString number(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("—");
}

}  // namespace

TestScoresModel::TestScoresModel(QObject* parent) : QAbstractTableModel(parent) {}

void TestScoresModel::setRows(std::vector<Row> rows) {
    beginResetModel();
    m_rows = std::move(rows);
    endResetModel();
}

int TestScoresModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int TestScoresModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TestScoresModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row& row = m_rows[std::size_t(index.row())];
    if (role == Qt::TextAlignmentRole && index.column() != Run)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && !row.score.ok()) return row.score.error;
    if (role != Qt::DisplayRole) return {};
    const models::Score& s = row.score;
    switch (index.column()) {
        case Run:
            return row.run;
        case Rms:
            return number(s.rms_um, 2);
        case Peak:
            return number(s.peak_um, 2);
        case Uncompensated:
            return number(s.uncompensated_rms_um, 2);
        case Reduction:
            return number(100 * s.reduction, 1);
        default:
            return {};
    }
}

QVariant TestScoresModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Run:
            return tr("Test run");
        case Rms:
            return tr("RMS (µm)");
        case Peak:
            return tr("Peak (µm)");
        case Uncompensated:
            return tr("Uncompensated RMS (µm)");
        case Reduction:
            return tr("Reduction (%)");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
