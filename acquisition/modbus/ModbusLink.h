#pragma once
// One Modbus client link (a libmodbus context), over TCP or RTU as its URL
// says: connect with a timeout, read and write registers in requests within
// the protocol's limits, errors that name the device, the registers and the
// system's reason. The transport differs only in how the context is opened;
// every request goes through the same code. A context belongs to one thread
// (docs/architecture.md): create the link on the thread that uses it.

#include <QString>
#include <cstdint>
#include <span>
#include <vector>

#include "acquisition/modbus/ModbusUrl.h"

struct _modbus;  // libmodbus's modbus_t, kept out of this header

namespace driftlab::modbus {

/// Function code 3 reads at most 125 registers, code 16 writes at most 123.
inline constexpr int kMaxReadRegisters = 125;
inline constexpr int kMaxWriteRegisters = 123;

class ModbusLink {
public:
    /// `response_timeout_s` bounds the TCP connect and every request.
    explicit ModbusLink(ModbusUrl url, double response_timeout_s = 1.0);
    ~ModbusLink();
    ModbusLink(const ModbusLink&) = delete;
    ModbusLink& operator=(const ModbusLink&) = delete;

    /// Connects (again, after close() or a lost connection): a TCP connect, or
    /// opening and configuring the serial device (stale bytes flushed).
    /// False with `error`.
    bool connect(QString* error);
    void close();
    bool isConnected() const { return m_connected; }

    /// Holding registers [address, address + count) into `out`, in requests of
    /// ≤ 125. False with `error`; anything but a Modbus exception (reset,
    /// timeout, a bad CRC, a response out of step) also closes the link.
    bool readRegisters(int address, int count, std::vector<std::uint16_t>& out, QString* error);
    /// Input registers (function 4), as readRegisters: many I/O modules keep
    /// their measurements there rather than in holding registers.
    bool readInputRegisters(int address, int count, std::vector<std::uint16_t>& out,
                            QString* error);
    /// Writes `values` from `address` on in requests of ≤ 123 (function 16).
    bool writeRegisters(int address, std::span<const std::uint16_t> values, QString* error);

    const ModbusUrl& url() const { return m_url; }
    /// Requests sent on this link (reads and writes), for the figures.
    int requests() const { return m_requests; }
    /// Write requests among them: a push refused before writing sent none.
    int writeRequests() const { return m_writes; }

private:
    /// The message for a failed request (errno `code`); closes the link
    /// unless the device answered with a Modbus exception.
    QString failure(int code, const QString& what, int address, int count);
    bool openContext(QString* error);
    bool read(bool input, int address, int count, std::vector<std::uint16_t>& out, QString* error);

    ModbusUrl m_url;
    double m_timeout_s;
    _modbus* m_context = nullptr;
    bool m_connected = false;
    int m_requests = 0;
    int m_writes = 0;
};

}  // namespace driftlab::modbus
