#include "db/SchemaMigrations.h"

#include <QDir>
#include <QFile>
#include <QSqlError>
#include <QSqlQuery>

#include "db/SampleBlocks.h"
#include "db/SqliteStatement.h"
#include "db/StoreBackend.h"

// The migrations live in a static library; its resources must be registered
// explicitly (from the global namespace, as Q_INIT_RESOURCE requires).
static void registerMigrationResources() {
    Q_INIT_RESOURCE(migrations);
}

namespace driftlab::db {
namespace {

QStringList migrationFiles(StoreBackend backend) {
    static const bool registered = (registerMigrationResources(), true);
    Q_UNUSED(registered);
    // Named NNNN_what.sql; the number is the version the migration produces.
    // Both back ends have the same numbers: a store says the same schema
    // version wherever it lives.
    return QDir(migrationFolder(backend))
        .entryList({QStringLiteral("*.sql")}, QDir::Files, QDir::Name);
}

/// Sets the schema version inside the migration's transaction: SQLite keeps it
/// in the file header, a server store in its mark (ServerStore.cpp).
QString versionStatement(StoreBackend backend, int version) {
    return backend == StoreBackend::Postgres
               ? QStringLiteral("UPDATE driftlab_store SET schema_version = %1").arg(version)
               : QStringLiteral("PRAGMA user_version = %1").arg(version);
}

/// Splits a migration into statements. Statements end with ';' at the end of a
/// line; migrations contain no triggers, so this is all the parsing they need.
QStringList statements(const QString& sql) {
    QStringList out;
    QString current;
    for (const QString& line : sql.split(QLatin1Char('\n'))) {
        if (line.trimmed().startsWith(QLatin1String("--"))) continue;
        current += line + QLatin1Char('\n');
        if (line.trimmed().endsWith(QLatin1Char(';'))) {
            out << current.trimmed();
            current.clear();
        }
    }
    if (!current.trimmed().isEmpty()) out << current.trimmed();
    return out;
}

}  // namespace

int latestSchemaVersion() {
    return int(migrationFiles(StoreBackend::Sqlite).size());
}

int latestSchemaVersion(StoreBackend backend) {
    return int(migrationFiles(backend).size());
}

int oldestReadableSchemaVersion() {
    return 3;
}

int schemaVersion(QSqlDatabase& db) {
    QSqlQuery q(db);
    const QString sql = backendOf(db) == StoreBackend::Postgres
                            ? QStringLiteral("SELECT schema_version FROM driftlab_store")
                            : QStringLiteral("PRAGMA user_version");
    return q.exec(sql) && q.next() ? q.value(0).toInt() : -1;
}

bool migrate(QSqlDatabase& db, QString* error, int target) {
    const StoreBackend backend = backendOf(db);
    const QStringList files = migrationFiles(backend);
    if (target < 0) target = int(files.size());
    int version = schemaVersion(db);
    if (version > int(files.size())) {
        *error =
            QStringLiteral("database schema v%1 is newer than this build (v%2); update DriftLab")
                .arg(version)
                .arg(files.size());
        return false;
    }
    for (; version < target; ++version) {
        const QString name = files[version];
        QFile file(migrationFolder(backend) + QLatin1Char('/') + name);
        file.open(QIODevice::ReadOnly);
        if (!db.transaction()) {
            *error = QStringLiteral("migration %1: %2").arg(name, db.lastError().text());
            return false;
        }
        QSqlQuery q(db);
        for (const QString& statement : statements(QString::fromUtf8(file.readAll()))) {
            if (!q.exec(statement)) {
                *error = QStringLiteral("migration %1 failed: %2").arg(name, q.lastError().text());
                db.rollback();
                return false;
            }
        }
        // What SQL alone cannot do: v3 packs the old per-value sample rows into blocks.
        if (version + 1 == 3 && backend == StoreBackend::Sqlite) {
            try {
                moveSampleRowsIntoBlocks(sqliteHandle(db));
            } catch (const QString& why) {
                *error = QStringLiteral("migration %1 failed: %2").arg(name, why);
                db.rollback();
                return false;
            }
        }
        if (!q.exec(versionStatement(backend, version + 1))) {
            *error = QStringLiteral("migration %1 failed: %2").arg(name, q.lastError().text());
            db.rollback();
            return false;
        }
        if (!db.commit()) {
            *error =
                QStringLiteral("migration %1: commit failed: %2").arg(name, db.lastError().text());
            db.rollback();
            return false;
        }
    }
    return true;
}

}  // namespace driftlab::db
