#pragma once
// The channels of a set-up as an editable table: id, quantity, role,
// location, position along the screw and the device channel each id maps to.
// A role that does not fit the quantity is refused (setData returns false);
// changing the quantity resets a role that no longer fits. The device column
// is derived: channel ids are the device map's ids (`driftlab-cli run
// --machine`), so it shows the register the id reads, or that none does.

#include <QAbstractTableModel>
#include <QStringList>
#include <optional>
#include <vector>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "core/domain/Channel.h"

namespace driftlab::ui {

class ChannelSetupModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        IdColumn,
        QuantityColumn,
        RoleColumn,
        LocationColumn,
        PositionColumn,
        DeviceColumn
    };
    /// The texts a combo-box editor offers for a cell (QStringList), empty
    /// for a free-text cell.
    enum Role { ChoicesRole = Qt::UserRole + 1 };

    explicit ChannelSetupModel(QObject* parent = nullptr);

    void setChannels(const std::vector<Channel>& channels);
    const std::vector<Channel>& channels() const { return m_channels; }
    /// The temperature module's map the ids refer to (nullopt: none, the
    /// simulated rig).
    void setDeviceMap(const std::optional<devices::ChannelRegisterMap>& map);

    /// What is wrong, one line per problem naming the row and the channel:
    /// "Channels row 3 (T_nut): role 'drift_x' does not fit a temperature".
    /// With `needDeviceMap`, a temperature id missing from the map is one.
    QStringList problems(bool needDeviceMap) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    bool insertRows(int row, int count, const QModelIndex& parent = {}) override;
    bool removeRows(int row, int count, const QModelIndex& parent = {}) override;

private:
    QStringList rowProblems(int row, bool needDeviceMap) const;
    const devices::ChannelSpec* deviceChannel(const QString& id) const;
    QString deviceText(const Channel& channel) const;

    std::vector<Channel> m_channels;
    std::optional<devices::ChannelRegisterMap> m_deviceMap;
};

}  // namespace driftlab::ui
