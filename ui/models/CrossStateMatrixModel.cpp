#include "ui/models/CrossStateMatrixModel.h"

#include <QFont>
#include <algorithm>
#include <cmath>

namespace driftlab::ui {

CrossStateMatrixModel::CrossStateMatrixModel(QObject* parent) : QAbstractTableModel(parent) {}

void CrossStateMatrixModel::setMatrices(
    const QStringList& runs, std::vector<std::pair<QString, models::CrossStateMatrix>> matrices) {
    beginResetModel();
    m_runs = runs;
    m_matrices = std::move(matrices);
    m_rows.clear();
    m_min_um = INFINITY;
    m_max_um = -INFINITY;
    for (std::size_t m = 0; m < m_matrices.size(); ++m) {
        const models::CrossStateMatrix& matrix = m_matrices[m].second;
        for (std::size_t i = 0; i < matrix.rms_um.size(); ++i) {
            m_rows.push_back({m_matrices[m].first, matrix.runs.value(qsizetype(i)), m, i});
            for (double v : matrix.rms_um[i])
                if (std::isfinite(v)) {
                    m_min_um = std::min(m_min_um, v);
                    m_max_um = std::max(m_max_um, v);
                }
        }
    }
    if (m_min_um > m_max_um) m_min_um = m_max_um = 0;
    endResetModel();
}

void CrossStateMatrixModel::clear() {
    setMatrices({}, {});
}

QColor CrossStateMatrixModel::rmsColour(double rms_um, double min_um, double max_um) {
    if (!std::isfinite(rms_um)) return QColor(Qt::lightGray);
    // Log scale: the matrix spans noise (0.4 µm) to a missed state (30 µm).
    const double lo = std::log(std::max(min_um, 1e-6));
    const double hi = std::log(std::max(max_um, 1e-6));
    const double t =
        hi > lo ? std::clamp((std::log(std::max(rms_um, 1e-6)) - lo) / (hi - lo), 0.0, 1.0) : 0.0;
    // Hue 120° (green) → 0° (red), pale enough for black text.
    return QColor::fromHsv(int(std::lround(120 * (1 - t))), 110, 245);
}

QStringList CrossStateMatrixModel::errors() const {
    QStringList lines;
    for (const auto& [name, matrix] : m_matrices)
        for (const QString& e : matrix.errors) lines << name + QStringLiteral(": ") + e;
    return lines;
}

int CrossStateMatrixModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int CrossStateMatrixModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_runs.size());
}

double CrossStateMatrixModel::cell(int row, int column) const {
    const Row& r = m_rows[std::size_t(row)];
    const auto& values = m_matrices[r.matrix].second.rms_um[r.index];
    return std::size_t(column) < values.size() ? values[std::size_t(column)] : NAN;
}

QVariant CrossStateMatrixModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const double v = cell(index.row(), index.column());
    const Row& r = m_rows[std::size_t(index.row())];
    const bool diagonal = std::size_t(index.column()) == r.index;
    switch (role) {
        case Qt::DisplayRole: {
            const QString text =
                std::isfinite(v) ? QString::number(v, 'f', 2) : QStringLiteral("—");
            return diagonal ? QStringLiteral("(%1)").arg(text) : text;
        }
        case Qt::BackgroundRole:
            return rmsColour(v, m_min_um, m_max_um);
        case Qt::ForegroundRole:
            return QColor(Qt::black);
        case Qt::FontRole: {
            QFont font;
            font.setItalic(diagonal);
            return font;
        }
        case Qt::TextAlignmentRole:
            return int(Qt::AlignRight | Qt::AlignVCenter);
        case Qt::ToolTipRole:
            return diagonal ? tr("%1 fitted on %2 and scored on it: a training score, %3 µm RMS")
                                  .arg(r.model, r.trainRun)
                                  .arg(v, 0, 'f', 2)
                            : tr("%1 fitted on %2, held-out RMS on %3: %4 µm")
                                  .arg(r.model, r.trainRun, m_runs.value(index.column()))
                                  .arg(v, 0, 'f', 2);
        case kRmsRole:
            return v;
        default:
            return {};
    }
}

QVariant CrossStateMatrixModel::headerData(int section, Qt::Orientation orientation,
                                           int role) const {
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    if (orientation == Qt::Horizontal) {
        if (section < 0 || section >= m_runs.size()) return {};
        return role == Qt::DisplayRole ? m_runs[section]
                                       : tr("scored on run %1").arg(m_runs[section]);
    }
    if (section < 0 || section >= int(m_rows.size())) return {};
    const Row& r = m_rows[std::size_t(section)];
    return role == Qt::DisplayRole ? QStringLiteral("%1 · %2").arg(r.model, r.trainRun)
                                   : tr("%1 fitted on run %2").arg(r.model, r.trainRun);
}

}  // namespace driftlab::ui
