#include "ui/models/DeviceHealthModel.h"

namespace driftlab::ui {

void DeviceHealthModel::reset(const QStringList& devices) {
    beginResetModel();
    m_rows.clear();
    for (const QString& d : devices) m_rows.push_back({d, DeviceHealth::Ok, tr("answering")});
    endResetModel();
}

void DeviceHealthModel::report(const QString& level, const QString& source,
                               const QString& message) {
    auto it = std::find_if(m_rows.begin(), m_rows.end(),
                           [&](const Row& r) { return r.device == source; });
    if (it == m_rows.end()) {
        // Engine notes (stabilisation, pauses) are not a device's health.
        if (source == QLatin1String("engine")) return;
        const int row = int(m_rows.size());
        beginInsertRows({}, row, row);
        m_rows.push_back({source, DeviceHealth::Ok, {}});
        endInsertRows();
        it = m_rows.begin() + row;
    }
    if (level == QLatin1String("error"))
        it->health = DeviceHealth::Lost;
    else if (level == QLatin1String("warning"))
        // A gap is reported when the device is back: it answers again.
        it->health =
            message.startsWith(QLatin1String("gap:")) ? DeviceHealth::Ok : DeviceHealth::Warning;
    it->message = message;
    const int row = int(it - m_rows.begin());
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

QColor DeviceHealthModel::colourOf(DeviceHealth health) {
    switch (health) {
        case DeviceHealth::Ok:
            return QColor(0x2e, 0xa0, 0x43);
        case DeviceHealth::Warning:
            return QColor(0xe0, 0xa0, 0x00);
        case DeviceHealth::Lost:
            return QColor(0xd0, 0x30, 0x30);
    }
    return {};
}

int DeviceHealthModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int DeviceHealthModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant DeviceHealthModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row& r = m_rows[std::size_t(index.row())];
    if (role == HealthRole) return int(r.health);
    if (role == Qt::DecorationRole && index.column() == DeviceColumn) return colourOf(r.health);
    if (role == Qt::ToolTipRole) return QStringLiteral("%1: %2").arg(r.device, r.message);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case DeviceColumn:
            return r.device;
        case HealthColumn:
            return r.health == DeviceHealth::Ok        ? tr("answering")
                   : r.health == DeviceHealth::Warning ? tr("warning")
                                                       : tr("lost");
        case MessageColumn:
            return r.message;
    }
    return {};
}

QVariant DeviceHealthModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case DeviceColumn:
            return tr("Device");
        case HealthColumn:
            return tr("Health");
        case MessageColumn:
            return tr("Last event");
    }
    return {};
}

}  // namespace driftlab::ui
