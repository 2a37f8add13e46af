#pragma once
// modbus://HOST:PORT[/UNIT], the address of a Modbus TCP device as the CLI and
// the settings name it.

#include <QString>
#include <optional>

namespace driftlab::modbus {

struct ModbusUrl {
    QString host;
    int port = 502;
    int unit = 1;  ///< Modbus unit (slave) id, 0…247

    /// "modbus://host:port/unit" (the unit only when not 1).
    QString toString() const;
    /// "host:port", how errors name the device.
    QString endpoint() const;
};

/// The URL, or nullopt with `error` saying what is wrong with `text`.
std::optional<ModbusUrl> parseModbusUrl(const QString& text, QString* error);

}  // namespace driftlab::modbus
