// CampaignStore::openOnServer: the store in a database on a PostgreSQL server
// (docs/lab-store.md). A SQLite store marks itself with its application_id; a
// server store with a one-row table, driftlab_store, that also holds the
// schema version (SQLite's user_version). DriftLab writes only into a
// database that holds its mark or nothing at all.
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>

#include "db/CampaignStore.h"
#include "db/SchemaMigrations.h"
#include "db/StoreBackend.h"

namespace driftlab::db {
namespace {

/// Runs one statement; returns the server's complaint, empty on success.
QString run(QSqlDatabase& db, const QString& sql) {
    QSqlQuery q(db);
    return q.exec(sql) ? QString() : q.lastError().text();
}

/// The tables of the database outside PostgreSQL's own schemas; nullopt with `why`.
std::optional<QStringList> userTables(QSqlDatabase& db, QString* why) {
    QSqlQuery q(db);
    if (!q.exec(QStringLiteral(
            "SELECT table_name FROM information_schema.tables WHERE table_schema NOT IN "
            "('pg_catalog', 'information_schema') ORDER BY table_name"))) {
        *why = QStringLiteral("cannot list its tables (%1)").arg(q.lastError().text());
        return std::nullopt;
    }
    QStringList tables;
    while (q.next()) tables << q.value(0).toString();
    return tables;
}

/// Creates the mark in an empty database, at schema version 0; the migrations follow.
QString markEmptyDatabase(QSqlDatabase& db) {
    if (!db.transaction()) return db.lastError().text();
    QString e =
        run(db, QStringLiteral("CREATE TABLE driftlab_store ("
                               "application_id BIGINT NOT NULL, "
                               "schema_version INTEGER NOT NULL, "
                               "created_at TEXT NOT NULL DEFAULT (to_char(now() AT TIME ZONE "
                               "'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"')))"));
    if (e.isEmpty())
        e = run(db, QStringLiteral("INSERT INTO driftlab_store (application_id, schema_version) "
                                   "VALUES (%1, 0)")
                        .arg(kStoreApplicationId));
    if (e.isEmpty() && !db.commit()) e = db.lastError().text();
    if (!e.isEmpty()) db.rollback();
    return e;
}

/// Why DriftLab may not open this database as `access` says; empty if it may
/// (creating the mark in an empty database opened for writing).
QString checkMark(QSqlDatabase& db, StoreAccess access) {
    const bool writing = access != StoreAccess::ReadOnly;
    QString why;
    const auto tables = userTables(db, &why);
    if (!tables) return why;
    if (tables->isEmpty()) {
        if (!writing) return QStringLiteral("no DriftLab store there (an empty database)");
        if (QString e = markEmptyDatabase(db); !e.isEmpty())
            return QStringLiteral("cannot create a store there (%1)").arg(e);
        return {};
    }
    QSqlQuery q(db);
    if (tables->contains(QStringLiteral("driftlab_store")) &&
        q.exec(QStringLiteral("SELECT application_id FROM driftlab_store")) && q.next() &&
        q.value(0).toLongLong() == qint64(kStoreApplicationId) && !q.next())
        return {};
    QStringList shown = tables->mid(0, 5);
    if (tables->size() > shown.size()) shown << QStringLiteral("…");
    why =
        QStringLiteral("not a DriftLab store (no DriftLab mark; tables: %1)").arg(shown.join(", "));
    if (writing)
        why += QStringLiteral("; DriftLab never writes into another application's database");
    return why;
}

QString checkSchema(QSqlDatabase& db, StoreAccess access) {
    const int version = schemaVersion(db);
    const int latest = latestSchemaVersion(StoreBackend::Postgres);
    if (version < 0) return QStringLiteral("cannot read its schema version");
    if (version > latest)
        return QStringLiteral("database schema v%1 is newer than this build (v%2); update DriftLab")
            .arg(version)
            .arg(latest);
    if (access == StoreAccess::ReadOnly && version < oldestReadableSchemaVersion())
        return QStringLiteral("store schema v%1 is older; open it once for writing to migrate")
            .arg(version);
    return {};
}

}  // namespace

bool CampaignStore::isServer() const {
    return backendOf(m_db) == StoreBackend::Postgres;
}

std::unique_ptr<CampaignStore> CampaignStore::openOnServer(const QString& location,
                                                           StoreAccess access, QString* error) {
    QString why;
    const auto url = parseServerStoreUrl(location, &why);
    if (!url) {
        *error = why;
        return nullptr;
    }
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), newConnectionName());
    auto fail = [&](const QString& reason) -> std::unique_ptr<CampaignStore> {
        *error = QStringLiteral("%1: %2").arg(url->display(), reason);
        const QString name = db.connectionName();
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(name);
        return nullptr;
    };
    if (!db.isValid())
        return fail(QStringLiteral(
            "Qt's PostgreSQL driver (QPSQL) is not installed (Debian: libqt6sql6-psql)"));
    db.setHostName(url->host);
    db.setPort(url->port);
    db.setDatabaseName(url->database);
    db.setUserName(url->user);
    db.setPassword(url->password);
    // A server that is away must not hang a command: libpq waits this long at most.
    QString options = QStringLiteral("connect_timeout=5;application_name=driftlab");
    if (!url->connectOptions.isEmpty()) options += QLatin1Char(';') + url->connectOptions;
    db.setConnectOptions(options);
    if (!db.open()) {
        // libpq's message spans lines; the reason a command gives is one line.
        const QString why = db.lastError().databaseText().isEmpty() ? db.lastError().text()
                                                                    : db.lastError().databaseText();
        return fail(QStringLiteral("cannot connect (%1)").arg(why.simplified()));
    }

    if (access == StoreAccess::ReadOnly) {
        if (QString r = checkMark(db, access); !r.isEmpty()) return fail(r);
        if (QString r = checkSchema(db, access); !r.isEmpty()) return fail(r);
        // Reading never writes: the server refuses any write on this session.
        if (QString e =
                run(db, QStringLiteral("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY"));
            !e.isEmpty())
            return fail(e);
        return std::unique_ptr<CampaignStore>(new CampaignStore(db, url->display(), access, {}));
    }

    // Rigs that open one store at once take turns to create and migrate it:
    // a session lock on the mark's id, released once the schema is current.
    const QString key = QString::number(kStoreApplicationId);
    if (QString e = run(db, QStringLiteral("SELECT pg_advisory_lock(%1)").arg(key)); !e.isEmpty())
        return fail(e);
    QString r = checkMark(db, access);
    if (r.isEmpty()) r = checkSchema(db, access);
    if (r.isEmpty() && !migrate(db, &r)) r = r.isEmpty() ? QStringLiteral("migration failed") : r;
    run(db, QStringLiteral("SELECT pg_advisory_unlock(%1)").arg(key));
    if (!r.isEmpty()) return fail(r);
    return std::unique_ptr<CampaignStore>(new CampaignStore(db, url->display(), access, {}));
}

}  // namespace driftlab::db
