#pragma once
// The host and port of a server URL (modbus://HOST:PORT, postgresql://USER@HOST:PORT/DB),
// checked part by part before QUrl reads the rest: QUrl refuses a bad port or
// host with one text for every part, whose "source was …" repeats the URL
// with its password, and an invalid QUrl has no text left to name it by.

#include <QString>
#include <QUrl>
#include <optional>

namespace driftlab {

/// SCHEME://[USER[:PASSWORD]@]HOST[:PORT] as written.
struct UrlAuthority {
    QString user;
    QString host;  ///< an IPv6 address without its brackets
    std::optional<int> port;
};

/// The authority of `url`, or nullopt with `why` naming the part that is
/// wrong: no host, a host that is neither a name nor an IP address, an IPv6
/// address without brackets, a port that is not 1…65535.
std::optional<UrlAuthority> parseUrlAuthority(const QString& url, QString* why);

/// `url` as written, without the password of its USER:PASSWORD@ (also when
/// QUrl refuses it): how messages name a URL.
QString urlWithoutPassword(const QString& url);

/// Why QUrl refused `url`, without the "source was …" that repeats it.
QString qtUrlError(const QUrl& url);

}  // namespace driftlab
