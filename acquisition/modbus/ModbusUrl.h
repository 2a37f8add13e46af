#pragma once
// The address of a Modbus device as the CLI and the settings name it:
//   modbus://HOST:PORT[/UNIT]                     Modbus TCP
//   modbus-rtu:///dev/ttyUSB0[?baud=…&parity=…&data=…&stop=…&unit=…]   Modbus RTU
// (docs/devices.md, "Addresses").

#include <QString>
#include <optional>

namespace driftlab::modbus {

enum class Transport { Tcp, Rtu };

/// A serial line's settings. The defaults are the Modbus over Serial Line
/// specification's (19200 baud, even parity, 8 data bits, 1 stop bit).
struct SerialLine {
    QString device;  ///< absolute path, e.g. /dev/ttyUSB0
    int baud = 19200;
    char parity = 'E';  ///< 'N', 'E' or 'O'
    int data_bits = 8;
    int stop_bits = 1;
};

struct ModbusUrl {
    ModbusUrl() = default;
    /// A Modbus TCP device.
    ModbusUrl(QString host, int port, int unit = 1)
        : host(std::move(host)), port(port), unit(unit) {}
    /// A Modbus RTU device on a serial line.
    static ModbusUrl rtu(SerialLine line, int unit = 1);

    Transport transport = Transport::Tcp;
    QString host;       ///< TCP only
    int port = 502;     ///< TCP only
    SerialLine serial;  ///< RTU only
    int unit = 1;       ///< Modbus unit (slave) id, 0…247 (1…247 on RTU)

    bool isRtu() const { return transport == Transport::Rtu; }
    /// The URL back, every serial setting spelled out; the TCP unit only when not 1.
    QString toString() const;
    /// How errors name the device: "host:port" or "/dev/ttyUSB0 19200 8E1 unit 1".
    QString endpoint() const;
};

/// The URL, or nullopt with `error` naming the part of `text` that is wrong.
std::optional<ModbusUrl> parseModbusUrl(const QString& text, QString* error);

/// Why `host` (a name or an IPv4/IPv6 address) gives no address to connect to
/// or listen on, as the system's resolver says it, or nothing. libmodbus does
/// this lookup too but reports its failure as "Connection refused".
std::optional<QString> hostLookupError(const QString& host);

}  // namespace driftlab::modbus
