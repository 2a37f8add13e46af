#include "ui/models/DriftSeriesModel.h"

#include <cmath>

namespace driftlab::ui {

DriftSeriesModel::DriftSeriesModel(QObject* parent) : QAbstractTableModel(parent) {}

void DriftSeriesModel::setDrift(const iso::RunDrift& drift) {
    beginResetModel();
    m_rows.clear();
    m_tilts = false;
    if (drift.ok() && drift.axis) {
        for (const iso::TargetDrift& t : drift.axis->targets)
            m_rows.push_back(
                {tr("%1 mm").arg(t.target_mm, 0, 'f', 3),
                 t.direction == Direction::Positive ? QStringLiteral("+") : QStringLiteral("−"),
                 t.drift});
    } else if (drift.ok() && drift.probes) {
        for (const iso::ProbeDrift& p : drift.probes->probes)
            m_rows.push_back({p.channel_id, toString(p.role), p.drift});
        for (const iso::TiltDrift& t : drift.probes->tilts)
            m_rows.push_back({tr("tilt %1 (%2−%3)").arg(t.name, t.to, t.from), tr("tilt"), t.drift,
                              t.max_tilt_urad});
        m_tilts = !drift.probes->tilts.empty();
    }
    endResetModel();
}

int DriftSeriesModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DriftSeriesModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : (m_tilts ? MaxTilt + 1 : MaxTilt);
}

QVariant DriftSeriesModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_rows.size())) return {};
    const Row& r = m_rows[std::size_t(index.row())];
    const iso::DriftSeries& s = r.series;
    double value = 0;
    switch (index.column()) {
        case Series:
            return role == Qt::DisplayRole || role == Qt::UserRole ? QVariant(r.name) : QVariant();
        case Kind:
            return role == Qt::DisplayRole || role == Qt::UserRole ? QVariant(r.kind) : QVariant();
        case MaxDrift:
            value = s.max_drift_um;
            break;
        case MaxDriftTime:
            value = s.max_drift_time_s;
            break;
        case Range:
            value = s.range_um;
            break;
        case Final:
            value = s.final_drift_um;
            break;
        case Stabilised:
            value = s.stabilised_time_s;
            break;
        case MaxTilt:
            value = r.max_tilt_urad;
            break;
        default:
            return {};
    }
    if (role == Qt::UserRole) return value;
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    if (index.column() == Stabilised)
        return std::isnan(value) ? tr("not stabilised") : QString::number(value, 'f', 0);
    if (index.column() == MaxDriftTime) return QString::number(value, 'f', 0);
    if (std::isnan(value)) return QStringLiteral("—");
    return QString::number(value, 'f', index.column() == MaxTilt ? 2 : 3);
}

QVariant DriftSeriesModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Series:
            return tr("Target / probe");
        case Kind:
            return tr("Dir / role");
        case MaxDrift:
            return tr("Max drift µm");
        case MaxDriftTime:
            return tr("At s");
        case Range:
            return tr("Range µm");
        case Final:
            return tr("Final µm");
        case Stabilised:
            return tr("Stabilised at s");
        case MaxTilt:
            return tr("Max tilt µrad");
    }
    return {};
}

}  // namespace driftlab::ui
