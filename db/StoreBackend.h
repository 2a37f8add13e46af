#pragma once
// Where the two back ends of the store differ, in one place (docs/lab-store.md):
// a store is a SQLite file (the default) or a database on a PostgreSQL server
// named by a URL, postgresql://USER@HOST[:PORT]/DB (the lab's shared store).
// Everything else speaks the SQL both understand through Qt SQL; only the
// SQLite hot paths (sample blocks, live logging) use the sqlite3 C API.

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QString>
#include <optional>

namespace driftlab::db {

enum class StoreBackend { Sqlite, Postgres };

/// The back end of an open store connection.
StoreBackend backendOf(const QSqlDatabase& db);

/// Whether `location` names a store on a server (postgresql:// or postgres://)
/// rather than a SQLite file.
bool isServerStoreUrl(const QString& location);

/// A parsed postgresql://USER[:PASSWORD]@HOST[:PORT]/DB[?OPTIONS] URL. A
/// password is better kept in ~/.pgpass or PGPASSWORD (libpq reads both).
struct ServerStoreUrl {
    QString user;
    QString password;
    QString host;
    int port = 5432;
    QString database;
    QString connectOptions;  ///< libpq options from the query, "key=value;key=value"
    /// The URL without its password, for messages.
    QString display() const;
};
/// Parses `url`; nullopt with `error` (naming what is wrong) when it is not usable.
std::optional<ServerStoreUrl> parseServerStoreUrl(const QString& url, QString* error);

/// The id the INSERT just run by `q` gave its row: the driver's last insert
/// id on SQLite; on PostgreSQL, whose driver reports only OIDs, lastval() of
/// the identity column's sequence.
qint64 insertedRowId(const QSqlDatabase& db, QSqlQuery& q);

/// A new Qt SQL connection name: one connection per open store.
QString newConnectionName();

/// The folder of the migration files of a back end, in the compiled-in resources.
QString migrationFolder(StoreBackend backend);

}  // namespace driftlab::db
