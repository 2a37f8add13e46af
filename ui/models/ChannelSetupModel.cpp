#include "ui/models/ChannelSetupModel.h"

#include <QBrush>
#include <QColor>
#include <cmath>

namespace driftlab::ui {
namespace {

constexpr Quantity kQuantities[] = {Quantity::Temperature, Quantity::Displacement, Quantity::Speed};
constexpr int kColumnCount = 6;

/// The role a channel gets when its quantity changes and the old role no
/// longer fits: the catch-all of the quantity.
ChannelRole defaultRoleFor(Quantity quantity) {
    switch (quantity) {
        case Quantity::Temperature:
            return ChannelRole::Other;
        case Quantity::Displacement:
            return ChannelRole::Drift;
        case Quantity::Speed:
            return ChannelRole::Spindle;
    }
    return ChannelRole::Other;
}

QString article(Quantity quantity) {
    return quantity == Quantity::Temperature    ? QStringLiteral("a temperature")
           : quantity == Quantity::Displacement ? QStringLiteral("a displacement")
                                                : QStringLiteral("a speed");
}

}  // namespace

ChannelSetupModel::ChannelSetupModel(QObject* parent) : QAbstractTableModel(parent) {}

void ChannelSetupModel::setChannels(const std::vector<Channel>& channels) {
    beginResetModel();
    m_channels = channels;
    endResetModel();
}

void ChannelSetupModel::setDeviceMap(const std::optional<devices::ChannelRegisterMap>& map) {
    m_deviceMap = map;
    if (!m_channels.empty())
        emit dataChanged(index(0, DeviceColumn), index(rowCount() - 1, DeviceColumn));
}

int ChannelSetupModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_channels.size());
}

int ChannelSetupModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : kColumnCount;
}

const devices::ChannelSpec* ChannelSetupModel::deviceChannel(const QString& id) const {
    if (!m_deviceMap) return nullptr;
    for (const auto& c : m_deviceMap->channels)
        if (c.id == id) return &c;
    return nullptr;
}

QString ChannelSetupModel::deviceText(const Channel& channel) const {
    if (!m_deviceMap) return tr("(simulated)");
    if (channel.quantity != Quantity::Temperature) return tr("(not on the module)");
    const devices::ChannelSpec* spec = deviceChannel(channel.id);
    if (!spec) return tr("not in %1").arg(m_deviceMap->name);
    return tr("%1 register %2, %3 × %4 %5")
        .arg(devices::toString(spec->kind))
        .arg(spec->address)
        .arg(devices::toString(spec->type))
        .arg(spec->scale)
        .arg(spec->unit);
}

QVariant ChannelSetupModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !checkIndex(index)) return {};
    const Channel& c = m_channels[std::size_t(index.row())];
    const int column = index.column();
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (column) {
            case IdColumn:
                return c.id;
            case QuantityColumn:
                return toString(c.quantity);
            case RoleColumn:
                return toString(c.role);
            case LocationColumn:
                return c.location;
            case PositionColumn:
                if (c.position_mm) return *c.position_mm;
                return role == Qt::EditRole ? QVariant(QString()) : QVariant(QStringLiteral("—"));
            case DeviceColumn:
                return deviceText(c);
        }
    }
    if (role == ChoicesRole) {
        if (column == QuantityColumn) {
            QStringList names;
            for (Quantity q : kQuantities) names << toString(q);
            return names;
        }
        if (column == RoleColumn) return roleNamesFor(c.quantity);
        return QStringList();
    }
    if (role == Qt::ForegroundRole && !rowProblems(index.row(), m_deviceMap.has_value()).isEmpty())
        return QBrush(QColor(0xc0, 0x20, 0x20));
    if (role == Qt::ToolTipRole) {
        const QStringList problems = rowProblems(index.row(), m_deviceMap.has_value());
        return problems.isEmpty() ? QVariant() : QVariant(problems.join(QLatin1Char('\n')));
    }
    return {};
}

bool ChannelSetupModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || !index.isValid() || !checkIndex(index)) return false;
    Channel& c = m_channels[std::size_t(index.row())];
    const QString text = value.toString().trimmed();
    switch (index.column()) {
        case IdColumn:
            c.id = text;
            break;
        case QuantityColumn: {
            const auto quantity = quantityFromString(text);
            if (!quantity) return false;
            c.quantity = *quantity;
            if (!roleAllowedFor(c.quantity, c.role)) c.role = defaultRoleFor(c.quantity);
            break;
        }
        case RoleColumn: {
            const auto channelRole = roleFromString(text);
            if (!channelRole || !roleAllowedFor(c.quantity, *channelRole)) return false;
            c.role = *channelRole;
            break;
        }
        case LocationColumn:
            c.location = text;
            break;
        case PositionColumn: {
            if (text.isEmpty() || text == QStringLiteral("—")) {
                c.position_mm.reset();
                break;
            }
            bool ok = false;
            const double position_mm = text.toDouble(&ok);
            if (!ok || !std::isfinite(position_mm)) return false;
            c.position_mm = position_mm;
            break;
        }
        default:
            return false;
    }
    // Problems and the device column of every row may change (duplicate ids).
    emit dataChanged(this->index(0, 0), this->index(rowCount() - 1, kColumnCount - 1));
    return true;
}

Qt::ItemFlags ChannelSetupModel::flags(const QModelIndex& index) const {
    if (!index.isValid() || !checkIndex(index)) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() != DeviceColumn) f |= Qt::ItemIsEditable;
    return f;
}

QVariant ChannelSetupModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    static const char* names[kColumnCount] = {"Id",       "Quantity",      "Role",
                                              "Location", "Position (mm)", "Device channel"};
    return section >= 0 && section < kColumnCount ? tr(names[section]) : QVariant();
}

bool ChannelSetupModel::insertRows(int row, int count, const QModelIndex& parent) {
    if (parent.isValid() || row < 0 || row > rowCount() || count < 1) return false;
    beginInsertRows({}, row, row + count - 1);
    for (int i = 0; i < count; ++i) {
        Channel c;
        c.id = QStringLiteral("T%1").arg(rowCount() + i + 1);
        m_channels.insert(m_channels.begin() + row + i, c);
    }
    endInsertRows();
    return true;
}

bool ChannelSetupModel::removeRows(int row, int count, const QModelIndex& parent) {
    if (parent.isValid() || row < 0 || count < 1 || row + count > rowCount()) return false;
    beginRemoveRows({}, row, row + count - 1);
    m_channels.erase(m_channels.begin() + row, m_channels.begin() + row + count);
    endRemoveRows();
    return true;
}

QStringList ChannelSetupModel::rowProblems(int row, bool needDeviceMap) const {
    const Channel& c = m_channels[std::size_t(row)];
    const QString where = tr("Channels row %1 (%2): ").arg(row + 1).arg(c.id);
    QStringList out;
    if (c.id.isEmpty())
        out << where + tr("id must not be empty");
    else if (!isValidIdentifier(c.id))
        out << where + tr("id must be letters, digits and _ only");
    else if (isAxisColumn(c.id))
        out << where + tr("id '%1' is an axis column").arg(c.id);
    for (int other = 0; other < row; ++other)
        if (!c.id.isEmpty() && m_channels[std::size_t(other)].id == c.id)
            out << where + tr("id is used by row %1 too").arg(other + 1);
    if (!roleAllowedFor(c.quantity, c.role))
        out << where + tr("role '%1' does not fit %2").arg(toString(c.role), article(c.quantity));
    if (c.position_mm && !std::isfinite(*c.position_mm))
        out << where + tr("position must be a number");
    if (needDeviceMap && c.quantity == Quantity::Temperature && !c.id.isEmpty()) {
        if (!m_deviceMap)
            out << where + tr("no device map to read it from");
        else if (!deviceChannel(c.id))
            out << where + tr("'%1' is not a channel of the device map %2 (its ids: %3)")
                               .arg(c.id, m_deviceMap->name, [this] {
                                   QStringList ids;
                                   for (const auto& d : m_deviceMap->channels) ids << d.id;
                                   return ids.join(QStringLiteral(", "));
                               }());
    }
    return out;
}

QStringList ChannelSetupModel::problems(bool needDeviceMap) const {
    QStringList out;
    if (m_channels.empty()) out << tr("Channels: at least one channel is needed");
    for (int row = 0; row < rowCount(); ++row) out << rowProblems(row, needDeviceMap);
    return out;
}

}  // namespace driftlab::ui
