#include "db/StoreBackend.h"

#include <QAtomicInteger>
#include <QSqlDriver>
#include <QUrl>
#include <QUrlQuery>

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
    text += host + QLatin1Char(':') + QString::number(port) + QLatin1Char('/') + database;
    return text;
}

std::optional<ServerStoreUrl> parseServerStoreUrl(const QString& text, QString* error) {
    const QUrl url(text, QUrl::StrictMode);
    auto fail = [&](const QString& why) -> std::optional<ServerStoreUrl> {
        *error = QStringLiteral("%1: %2 (expected postgresql://USER@HOST[:PORT]/DB)")
                     .arg(QUrl(text).toDisplayString(QUrl::RemovePassword), why);
        return std::nullopt;
    };
    if (!url.isValid()) return fail(QStringLiteral("not a valid URL (%1)").arg(url.errorString()));
    if (!isServerStoreUrl(text)) return fail(QStringLiteral("not a postgresql:// URL"));
    ServerStoreUrl out;
    out.user = url.userName();
    out.password = url.password();
    out.host = url.host();
    out.port = url.port(5432);
    out.database = url.path().mid(1);
    if (out.host.isEmpty()) return fail(QStringLiteral("no server host"));
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
