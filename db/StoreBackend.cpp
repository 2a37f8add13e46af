#include "db/StoreBackend.h"

#include <QAtomicInteger>
#include <QSqlDriver>
#include <QUrl>
#include <QUrlQuery>

#include "core/domain/ServerUrl.h"

namespace driftlab::db {

StoreBackend backendOf(const QSqlDatabase& db) {
    return db.driverName() == QLatin1String("QPSQL") ? StoreBackend::Postgres
                                                     : StoreBackend::Sqlite;
}

bool isServerStoreUrl(const QString& location) {
    return location.startsWith(QLatin1String("postgresql://")) ||
           location.startsWith(QLatin1String("postgres://"));
}

QString ServerStoreUrl::display() const {
    QString text = QStringLiteral("postgresql://");
    if (!user.isEmpty()) text += user + QLatin1Char('@');
    // An IPv6 address needs its brackets back to be read as host:port.
    text += (host.contains(QLatin1Char(':')) ? QLatin1Char('[') + host + QLatin1Char(']') : host) +
            QLatin1Char(':') + QString::number(port) + QLatin1Char('/') + database;
    return text;
}

std::optional<ServerStoreUrl> parseServerStoreUrl(const QString& text, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<ServerStoreUrl> {
        *error = QStringLiteral("%1: %2 (expected postgresql://USER@HOST[:PORT]/DB)")
                     .arg(urlWithoutPassword(text), why);
        return std::nullopt;
    };
    if (!isServerStoreUrl(text)) return fail(QStringLiteral("not a postgresql:// URL"));
    QString why;
    const auto authority = parseUrlAuthority(text, &why);
    if (!authority) return fail(why);
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid()) return fail(QStringLiteral("not a valid URL (%1)").arg(qtUrlError(url)));
    ServerStoreUrl out;
    out.user = url.userName();
    out.password = url.password();
    out.host = authority->host;
    out.port = authority->port.value_or(5432);
    out.database = url.path().mid(1);
    if (out.database.isEmpty() || out.database.contains(QLatin1Char('/')))
        return fail(QStringLiteral("no database name after the host"));
    QStringList options;
    for (const auto& [key, value] : QUrlQuery(url).queryItems(QUrl::FullyDecoded))
        options << key + QLatin1Char('=') + value;
    out.connectOptions = options.join(QLatin1Char(';'));
    return out;
}

qint64 insertedRowId(const QSqlDatabase& db, QSqlQuery& q) {
    if (backendOf(db) == StoreBackend::Sqlite) return q.lastInsertId().toLongLong();
    QSqlQuery last(db);
    return last.exec(QStringLiteral("SELECT lastval()")) && last.next() ? last.value(0).toLongLong()
                                                                        : 0;
}

QString newConnectionName() {
    static QAtomicInteger<int> counter;
    return QStringLiteral("driftlab-store-%1").arg(counter.fetchAndAddRelaxed(1));
}

QString migrationFolder(StoreBackend backend) {
    return backend == StoreBackend::Postgres ? QStringLiteral(":/driftlab/migrations/postgresql")
                                             : QStringLiteral(":/driftlab/migrations");
}

}  // namespace driftlab::db
