#include "acquisition/modbus/ModbusUrl.h"

#include <QUrl>

namespace driftlab::modbus {

QString ModbusUrl::toString() const {
    QString text = QStringLiteral("modbus://%1").arg(endpoint());
    if (unit != 1) text += QStringLiteral("/%1").arg(unit);
    return text;
}

QString ModbusUrl::endpoint() const {
    // An IPv6 literal needs its brackets back to be read as host:port.
    const QString shown = host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host;
    return QStringLiteral("%1:%2").arg(shown).arg(port);
}

std::optional<ModbusUrl> parseModbusUrl(const QString& text, QString* error) {
    const auto fail = [&](const QString& why) {
        *error = QStringLiteral("'%1': %2 (expected modbus://HOST:PORT[/UNIT])").arg(text, why);
        return std::nullopt;
    };
    if (!text.startsWith(QLatin1String("modbus://"))) return fail(QStringLiteral("not modbus://"));
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid()) return fail(url.errorString());
    if (url.host().isEmpty()) return fail(QStringLiteral("no host"));
    if (!url.userInfo().isEmpty() || url.hasQuery() || url.hasFragment())
        return fail(QStringLiteral("user, query or fragment are not part of a Modbus address"));
    ModbusUrl result;
    result.host = url.host();
    // Modbus TCP has a well-known port, but a forgotten port on a gateway that
    // serves several devices is a likelier mistake than a wish for 502.
    if (url.port() <= 0) return fail(QStringLiteral("no port"));
    result.port = url.port();
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

}  // namespace driftlab::modbus
