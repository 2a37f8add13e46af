#pragma once
// A temperature module on Modbus TCP or RTU: all channels of a
// ChannelRegisterMap read in as few requests as the map allows (contiguous
// registers of one kind share a request of ≤ 125), decoded into one reading.
// Like ModbusLink it belongs to the thread that created it.

#include <QDateTime>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "acquisition/devices/PolledDevice.h"
#include "acquisition/modbus/ModbusUrl.h"

namespace driftlab::modbus {
class ModbusLink;
}

namespace driftlab::devices {

enum class ChannelStatus { Ok, InvalidRaw, NotRead };

/// One poll of every channel, in the map's channel order.
struct TemperatureReading {
    QDateTime time_utc;
    std::vector<double> values;  ///< engineering units (the map's); NaN unless Ok
    std::vector<ChannelStatus> status;
    std::vector<std::uint32_t> raw;  ///< raw bit patterns, for diagnosis
    /// Why channels are NotRead (a Modbus exception on their block), else empty.
    QString warning;
};

/// One read request: `count` registers of `kind` from `address`.
struct ReadBlock {
    RegisterKind kind = RegisterKind::Input;
    int address = 0;
    int count = 0;
};

/// The requests that cover every channel: contiguous channels of one kind are
/// merged up to `max_registers`; a gap starts a new request because reading
/// unmapped registers is an exception on many modules.
std::vector<ReadBlock> planReads(const ChannelRegisterMap& map, int max_registers = 125);

class TemperatureModule : public PolledDevice {
public:
    TemperatureModule(ChannelRegisterMap map, modbus::ModbusUrl url,
                      double response_timeout_s = 1.0);
    ~TemperatureModule() override;
    TemperatureModule(const TemperatureModule&) = delete;
    TemperatureModule& operator=(const TemperatureModule&) = delete;

    bool connect(QString* error) override;
    void close() override;
    bool isConnected() const;

    /// Every channel, or nullopt with `error` when the link failed (the link
    /// is then closed). A Modbus exception on one block only marks its
    /// channels NotRead, with the reason in the reading's warning.
    std::optional<TemperatureReading> read(QString* error);
    /// read() for DeviceWorker: the reading in a QVariant.
    std::optional<PolledReading> poll(QString* error) override;

    const ChannelRegisterMap& map() const { return m_map; }
    const std::vector<ReadBlock>& plan() const { return m_plan; }
    /// Requests sent so far (for tests of the grouping).
    int requests() const;

private:
    ChannelRegisterMap m_map;
    std::vector<ReadBlock> m_plan;
    std::unique_ptr<modbus::ModbusLink> m_link;
};

QString toString(ChannelStatus status);

}  // namespace driftlab::devices

Q_DECLARE_METATYPE(driftlab::devices::TemperatureReading)
