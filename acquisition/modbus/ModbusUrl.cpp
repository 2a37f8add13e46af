#include "acquisition/modbus/ModbusUrl.h"

#include <netdb.h>
#include <sys/socket.h>

#include <QSet>
#include <QUrl>

#include "core/domain/ServerUrl.h"

namespace driftlab::modbus {
namespace {

const QLatin1String kTcpScheme("modbus://");
const QLatin1String kRtuScheme("modbus-rtu://");

std::optional<ModbusUrl> parseTcp(const QString& text, QString* error) {
    const auto fail = [&](const QString& why) {
        *error = QStringLiteral("'%1': %2 (expected modbus://HOST:PORT[/UNIT])").arg(text, why);
        return std::nullopt;
    };
    QString why;
    const auto authority = parseUrlAuthority(text, &why);
    if (!authority) return fail(why);
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid()) return fail(qtUrlError(url));
    if (!url.userInfo().isEmpty() || url.hasQuery() || url.hasFragment())
        return fail(QStringLiteral("user, query or fragment are not part of a Modbus address"));
    ModbusUrl result;
    result.host = authority->host;
    // Modbus TCP has a well-known port, but a forgotten port on a gateway that
    // serves several devices is a likelier mistake than a wish for 502.
    if (!authority->port) return fail(QStringLiteral("no port"));
    result.port = *authority->port;
    QString path = url.path();
    if (path.endsWith(QLatin1Char('/'))) path.chop(1);
    if (!path.isEmpty()) {
        bool ok = false;
        result.unit = path.mid(1).toInt(&ok);
        if (!ok || result.unit < 0 || result.unit > 247)
            return fail(QStringLiteral("unit '%1' is not a number from 0 to 247").arg(path.mid(1)));
    }
    return result;
}

std::optional<ModbusUrl> parseRtu(const QString& text, QString* error) {
    const auto fail = [&](const QString& why) {
        *error = QStringLiteral(
                     "'%1': %2 (expected modbus-rtu:///dev/DEVICE"
                     "[?baud=19200&parity=E&data=8&stop=1&unit=1])")
                     .arg(text, why);
        return std::nullopt;
    };
    const QString rest = text.mid(kRtuScheme.size());
    const QString device = rest.section(QLatin1Char('?'), 0, 0);
    if (device.isEmpty()) return fail(QStringLiteral("no serial device"));
    if (!device.startsWith(QLatin1Char('/')))
        return fail(QStringLiteral("device '%1' is not an absolute path "
                                   "(three slashes: modbus-rtu:///dev/ttyUSB0)")
                        .arg(device));
    SerialLine line;
    line.device = device;
    int unit = 1;
    QSet<QString> seen;
    const QString query = rest.section(QLatin1Char('?'), 1);
    for (const QString& item : query.split(QLatin1Char('&'), Qt::SkipEmptyParts)) {
        const QString key = item.section(QLatin1Char('='), 0, 0);
        const QString value = item.section(QLatin1Char('='), 1);
        if (!item.contains(QLatin1Char('=')) || value.isEmpty())
            return fail(QStringLiteral("'%1' has no value").arg(key));
        if (seen.contains(key)) return fail(QStringLiteral("'%1' given twice").arg(key));
        seen.insert(key);
        bool ok = false;
        const int number = value.toInt(&ok);
        const auto bad = [&](const QString& allowed) {
            return fail(QStringLiteral("%1 '%2' is not %3").arg(key, value, allowed));
        };
        if (key == QLatin1String("baud")) {
            if (!ok || number < 300 || number > 4'000'000)
                return bad(QStringLiteral("300…4000000"));
            line.baud = number;
        } else if (key == QLatin1String("parity")) {
            const QString p = value.toUpper();
            if (p != QLatin1String("N") && p != QLatin1String("E") && p != QLatin1String("O"))
                return bad(QStringLiteral("N, E or O"));
            line.parity = p.at(0).toLatin1();
        } else if (key == QLatin1String("data")) {
            // RTU frames are 8-bit binary; 7 data bits is Modbus ASCII.
            if (!ok || number != 8) return bad(QStringLiteral("8 (RTU frames carry 8 data bits)"));
            line.data_bits = number;
        } else if (key == QLatin1String("stop")) {
            if (!ok || (number != 1 && number != 2)) return bad(QStringLiteral("1 or 2"));
            line.stop_bits = number;
        } else if (key == QLatin1String("unit")) {
            // 0 is the broadcast address on a serial line: nothing answers it.
            if (!ok || number < 1 || number > 247) return bad(QStringLiteral("1…247"));
            unit = number;
        } else {
            return fail(
                QStringLiteral("unknown setting '%1' (baud, parity, data, stop, unit)").arg(key));
        }
    }
    return ModbusUrl::rtu(line, unit);
}

}  // namespace

ModbusUrl ModbusUrl::rtu(SerialLine line, int unit) {
    ModbusUrl url;
    url.transport = Transport::Rtu;
    url.serial = std::move(line);
    url.unit = unit;
    return url;
}

QString ModbusUrl::toString() const {
    if (isRtu())
        return QStringLiteral("modbus-rtu://%1?baud=%2&parity=%3&data=%4&stop=%5&unit=%6")
            .arg(serial.device)
            .arg(serial.baud)
            .arg(QLatin1Char(serial.parity))
            .arg(serial.data_bits)
            .arg(serial.stop_bits)
            .arg(unit);
    QString text = QStringLiteral("modbus://%1").arg(endpoint());
    if (unit != 1) text += QStringLiteral("/%1").arg(unit);
    return text;
}

QString ModbusUrl::endpoint() const {
    if (isRtu())
        return QStringLiteral("%1 %2 %3%4%5 unit %6")
            .arg(serial.device)
            .arg(serial.baud)
            .arg(serial.data_bits)
            .arg(QLatin1Char(serial.parity))
            .arg(serial.stop_bits)
            .arg(unit);
    // An IPv6 literal needs its brackets back to be read as host:port.
    const QString shown = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
    return QStringLiteral("%1:%2").arg(shown).arg(port);
}

std::optional<QString> hostLookupError(const QString& host) {
    // getaddrinfo as libmodbus's _pi functions call it, so that a host passes
    // here exactly when libmodbus finds an address for it. (QHostInfo would
    // need a QCoreApplication, which a library caller need not have.)
    addrinfo hints{};
    hints.ai_flags = AI_ADDRCONFIG;
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const int rc = getaddrinfo(host.toUtf8().constData(), nullptr, &hints, &found);
    if (found) freeaddrinfo(found);
    if (rc == 0) return std::nullopt;
    return QString::fromLocal8Bit(gai_strerror(rc));
}

std::optional<ModbusUrl> parseModbusUrl(const QString& text, QString* error) {
    if (text.startsWith(kTcpScheme)) return parseTcp(text, error);
    if (text.startsWith(kRtuScheme)) return parseRtu(text, error);
    *error = QStringLiteral(
                 "'%1': neither modbus://HOST:PORT[/UNIT] (TCP) nor "
                 "modbus-rtu:///dev/DEVICE?… (RTU)")
                 .arg(text);
    return std::nullopt;
}

}  // namespace driftlab::modbus
