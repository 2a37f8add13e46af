#include "acquisition/modbus/ModbusLink.h"

#include <modbus.h>

#include <QFile>

#include <algorithm>
#include <cerrno>
#include <cmath>

namespace driftlab::modbus {
namespace {

void splitSeconds(double seconds, std::uint32_t* whole, std::uint32_t* micro) {
    const double clamped = std::clamp(seconds, 0.001, 3600.0);
    *whole = std::uint32_t(clamped);
    *micro = std::uint32_t(std::lround((clamped - *whole) * 1e6)) % 1000000u;
}

}  // namespace

ModbusLink::ModbusLink(ModbusUrl url, double response_timeout_s)
    : m_url(std::move(url)), m_timeout_s(response_timeout_s) {}

ModbusLink::~ModbusLink() {
    close();
}

void ModbusLink::close() {
    if (!m_context) return;
    modbus_close(m_context);
    modbus_free(m_context);
    m_context = nullptr;
    m_connected = false;
}

bool ModbusLink::openContext(QString* error) {
    if (m_url.isRtu()) {
        const SerialLine& line = m_url.serial;
        const QByteArray device = QFile::encodeName(line.device);
        m_context = modbus_new_rtu(device.constData(), line.baud, line.parity, line.data_bits,
                                   line.stop_bits);
    } else {
        // The _pi variant resolves host names as well as IPv4/IPv6 literals.
        const QByteArray host = m_url.host.toUtf8();
        const QByteArray service = QByteArray::number(m_url.port);
        m_context = modbus_new_tcp_pi(host.constData(), service.constData());
    }
    if (m_context) return true;
    *error = QStringLiteral("%1: cannot create a Modbus context: %2")
                 .arg(m_url.endpoint(), QString::fromLocal8Bit(modbus_strerror(errno)));
    return false;
}

bool ModbusLink::connect(QString* error) {
    close();
    if (!m_url.isRtu()) {
        // libmodbus reports a name that does not resolve as "Connection
        // refused", which sends the user looking for a server that is down.
        if (const auto why = hostLookupError(m_url.host)) {
            *error = QStringLiteral("%1: cannot connect: host '%2' could not be resolved (%3)")
                         .arg(m_url.endpoint(), m_url.host, *why);
            return false;
        }
    }
    if (!openContext(error)) return false;
    std::uint32_t seconds = 0, micro = 0;
    splitSeconds(m_timeout_s, &seconds, &micro);
    // libmodbus bounds the TCP connect by the response timeout too.
    modbus_set_response_timeout(m_context, seconds, micro);
    modbus_set_slave(m_context, m_url.unit);
    if (modbus_connect(m_context) == -1) {
        *error = QStringLiteral("%1: cannot %2: %3")
                     .arg(m_url.endpoint(),
                          m_url.isRtu() ? QStringLiteral("open the serial device")
                                        : QStringLiteral("connect"),
                          QString::fromLocal8Bit(modbus_strerror(errno)));
        close();
        return false;
    }
    // RTU has no transaction ids: a late answer to a request of the previous
    // connection would pass for the answer to the next one.
    if (m_url.isRtu()) modbus_flush(m_context);
    m_connected = true;
    return true;
}

QString ModbusLink::failure(int code, const QString& what, int address, int count) {
    const QString text = QStringLiteral("%1: %2 registers %3–%4: %5")
                             .arg(m_url.endpoint(), what)
                             .arg(address)
                             .arg(address + count - 1)
                             .arg(QString::fromLocal8Bit(modbus_strerror(code)));
    // A Modbus exception is an answer; anything else (reset, timeout, a bad
    // CRC, a response out of step) leaves the stream unusable until reconnected.
    const bool exception = code >= EMBXILFUN && code <= EMBXGTAR;
    if (!exception) close();
    return text;
}

bool ModbusLink::readRegisters(int address, int count, std::vector<std::uint16_t>& out,
                               QString* error) {
    return read(false, address, count, out, error);
}

bool ModbusLink::readInputRegisters(int address, int count, std::vector<std::uint16_t>& out,
                                    QString* error) {
    return read(true, address, count, out, error);
}

bool ModbusLink::read(bool input, int address, int count, std::vector<std::uint16_t>& out,
                      QString* error) {
    out.assign(std::size_t(std::max(count, 0)), 0);
    if (!m_connected) {
        *error = QStringLiteral("%1: not connected").arg(m_url.endpoint());
        return false;
    }
    for (int done = 0; done < count;) {
        const int n = std::min(kMaxReadRegisters, count - done);
        ++m_requests;
        const int got =
            input ? modbus_read_input_registers(m_context, address + done, n, out.data() + done)
                  : modbus_read_registers(m_context, address + done, n, out.data() + done);
        if (got != n) {
            const int code = errno;
            *error =
                failure(code, input ? QStringLiteral("reading input") : QStringLiteral("reading"),
                        address + done, n);
            return false;
        }
        done += n;
    }
    return true;
}

bool ModbusLink::writeRegisters(int address, std::span<const std::uint16_t> values,
                                QString* error) {
    if (!m_connected) {
        *error = QStringLiteral("%1: not connected").arg(m_url.endpoint());
        return false;
    }
    const int count = int(values.size());
    for (int done = 0; done < count;) {
        const int n = std::min(kMaxWriteRegisters, count - done);
        ++m_requests;
        ++m_writes;
        if (modbus_write_registers(m_context, address + done, n, values.data() + done) != n) {
            const int code = errno;
            *error = failure(code, QStringLiteral("writing"), address + done, n);
            return false;
        }
        done += n;
    }
    return true;
}

}  // namespace driftlab::modbus
