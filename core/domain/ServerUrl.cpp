#include "core/domain/ServerUrl.h"

#include <QRegularExpression>

namespace driftlab {

std::optional<UrlAuthority> parseUrlAuthority(const QString& url, QString* why) {
    const auto fail = [&](const QString& text) -> std::optional<UrlAuthority> {
        *why = text;
        return std::nullopt;
    };
    static const QRegularExpression form(QStringLiteral("^[A-Za-z][A-Za-z0-9+.-]*://([^/?#]*)"));
    const QRegularExpressionMatch m = form.match(url);
    if (!m.hasMatch()) return fail(QStringLiteral("not SCHEME://HOST"));
    QString rest = m.captured(1);
    UrlAuthority out;
    if (const qsizetype at = rest.lastIndexOf(QLatin1Char('@')); at >= 0) {
        out.user = rest.left(at).section(QLatin1Char(':'), 0, 0);
        rest = rest.mid(at + 1);
    }
    QString port;
    bool hasPort = false;
    if (rest.startsWith(QLatin1Char('['))) {
        const qsizetype close = rest.indexOf(QLatin1Char(']'));
        if (close < 0) return fail(QStringLiteral("host '%1' has no closing ']'").arg(rest));
        out.host = rest.mid(1, close - 1);
        const QString after = rest.mid(close + 1);
        if (!after.isEmpty() && !after.startsWith(QLatin1Char(':')))
            return fail(
                QStringLiteral("'%1' after the host [%2] is not :PORT").arg(after, out.host));
        hasPort = !after.isEmpty();
        port = after.mid(1);
    } else {
        if (rest.count(QLatin1Char(':')) > 1)
            return fail(QStringLiteral("host and port '%1' have more than one ':': an IPv6 "
                                       "address goes in brackets, e.g. [::1]:502")
                            .arg(rest));
        const qsizetype colon = rest.indexOf(QLatin1Char(':'));
        out.host = colon < 0 ? rest : rest.left(colon);
        hasPort = colon >= 0;
        port = rest.mid(colon + 1);
    }
    if (out.host.isEmpty()) return fail(QStringLiteral("no host"));
    // QUrl's own rule for a host: a name (IDNA too), an IPv4 or an IPv6 address.
    QUrl probe;
    probe.setHost(out.host, QUrl::StrictMode);
    if (!probe.isValid() || probe.host().isEmpty())
        return fail(
            QStringLiteral("host '%1' is neither a host name nor an IP address").arg(out.host));
    if (hasPort) {
        static const QRegularExpression digits(QStringLiteral("^[0-9]{1,5}$"));
        const int number = digits.match(port).hasMatch() ? port.toInt() : 0;
        if (number < 1 || number > 65535)
            return fail(QStringLiteral("port '%1' is not a number from 1 to 65535").arg(port));
        out.port = number;
    }
    return out;
}

QString urlWithoutPassword(const QString& url) {
    // Up to the last '@' of the authority: a password may hold an unencoded '@'.
    static const QRegularExpression password(
        QStringLiteral("^([A-Za-z][A-Za-z0-9+.-]*://[^/?#:@]*):[^/?#]*@"));
    QString text = url;
    return text.replace(password, QStringLiteral("\\1@"));
}

QString qtUrlError(const QUrl& url) {
    return url.errorString().section(QStringLiteral("; source was"), 0, 0);
}

}  // namespace driftlab
