#include "db/CampaignStore.h"

#include <signal.h>
#include <unistd.h>
#include <cerrno>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryFile>
#include <utility>

#include "core/bundle/RegularFile.h"
#include "db/SchemaMigrations.h"
#include "db/SqlValues.h"
#include "db/SqliteStatement.h"
#include "db/StoreBackend.h"
#include "db/StoreInspection.h"

namespace driftlab::db {
namespace {

/// Runs one statement; returns SQLite's complaint, empty on success. `value`
/// receives the first column of the first row.
QString run(QSqlDatabase& db, const QString& sql, QVariant* value = nullptr) {
    QSqlQuery q(db);
    if (!q.exec(sql)) return q.lastError().text();
    if (value) *value = q.next() ? q.value(0) : QVariant();
    return {};
}

/// Whether a statement failed because another connection holds the store's lock.
bool isLockedOut(const QSqlError& error) {
    const int code = error.nativeErrorCode().toInt() & 0xFF;  // the primary result code
    return code == SQLITE_BUSY || code == SQLITE_LOCKED;
}

/// PRAGMA journal_mode = WAL, waiting for another process's lock as long as the
/// busy timeout would. SQLite does not call its busy handler for a change of
/// journal mode (the statement has read the file before it needs the file to
/// itself), so without this wait a store locked for a moment, by a writer
/// between two commits, would be refused at once.
QSqlError switchToWal(QSqlDatabase& db, QVariant* mode) {
    QElapsedTimer waited;
    waited.start();
    for (;;) {
        QSqlQuery q(db);
        if (q.exec(QStringLiteral("PRAGMA journal_mode = WAL"))) {
            *mode = q.next() ? q.value(0) : QVariant();
            return {};
        }
        if (!isLockedOut(q.lastError()) || waited.hasExpired(kStoreBusyTimeout_ms))
            return q.lastError();
        sqlite3_sleep(20);
    }
}

/// Why the inspected file is not one DriftLab may open with `access`; empty if it may.
QString refusal(const StoreFileInfo& info, StoreAccess access) {
    const bool writing = access != StoreAccess::ReadOnly;
    // A store of the builds before application_id: a schema version and a campaign table.
    const bool legacy = info.applicationId == 0 && info.userVersion >= 1 &&
                        info.tables.contains(QStringLiteral("campaign"));
    // An empty database holds nothing of anyone's; a store is built in it when writing.
    const bool empty = info.applicationId == 0 && info.tables.isEmpty();
    if (info.applicationId == kStoreApplicationId || legacy || (empty && writing)) return {};
    QStringList shown = info.tables.mid(0, 5);
    if (info.tables.size() > shown.size()) shown << QStringLiteral("…");
    QString why = QStringLiteral("not a DriftLab store (application_id 0x%1, %2)")
                      .arg(info.applicationId, 8, 16, QLatin1Char('0'))
                      .arg(shown.isEmpty() ? QStringLiteral("no tables")
                                           : QStringLiteral("tables: ") + shown.join(", "));
    if (writing)
        why += QStringLiteral("; DriftLab never writes into another application's database");
    return why;
}

QString schemaRefusal(const StoreFileInfo& info, StoreAccess access) {
    if (info.userVersion > latestSchemaVersion())
        return QStringLiteral("database schema v%1 is newer than this build (v%2); update DriftLab")
            .arg(info.userVersion)
            .arg(latestSchemaVersion());
    // Reading never migrates: that would write, and may be impossible (read-only media).
    if (access == StoreAccess::ReadOnly && info.userVersion < oldestReadableSchemaVersion())
        return QStringLiteral("store schema v%1 is older; open it once for writing to migrate")
            .arg(info.userVersion);
    return {};
}

void removeWithSideFiles(const QString& path) {
    for (const char* suffix : {"-wal", "-shm", "-journal", ""})
        QFile::remove(path + QLatin1String(suffix));
}

/// Removes `.NAME.<pid>-XXXXXX.new` stores (with their -wal/-shm) beside the
/// target whose process no longer runs: an import killed before it published.
void sweepPartialStoresOfDeadImports(const QFileInfo& target) {
    const QString prefix = QStringLiteral(".") + target.fileName() + QLatin1Char('.');
    const QDir folder = target.absoluteDir();
    for (const QString& name :
         folder.entryList({prefix + QStringLiteral("*.new")}, QDir::Files | QDir::Hidden)) {
        bool ok = false;
        const qint64 pid = name.mid(prefix.size()).section(QLatin1Char('-'), 0, 0).toLongLong(&ok);
        if (ok && pid > 0 && kill(pid_t(pid), 0) != 0 && errno == ESRCH)
            removeWithSideFiles(folder.filePath(name));
    }
}

/// A new, empty file beside `path` to build a new store in: renamed into place
/// only once complete, so a failed import leaves nothing at `path`.
/// Its name carries the creator's pid, so that the partial store of an import
/// that was killed (power cut, OOM killer) is recognised and swept by the next.
QString reserveTemporaryFile(const QString& path, QString* why) {
    const QFileInfo target(path);
    sweepPartialStoresOfDeadImports(target);
    QTemporaryFile file(target.absolutePath() + QStringLiteral("/.") + target.fileName() +
                        QStringLiteral(".%1-XXXXXX.new").arg(getpid()));
    file.setAutoRemove(false);
    if (!file.open()) {
        *why = QStringLiteral("cannot create a store there (%1)").arg(file.errorString());
        return {};
    }
    // The permissions SQLite gives the files it creates, not QTemporaryFile's 0600.
    file.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
    return file.fileName();
}

}  // namespace

QString storeWriteCondition(int sqliteResultCode) {
    switch (sqliteResultCode & 0xFF) {
        case SQLITE_BUSY:
        case SQLITE_LOCKED:
            return QStringLiteral(
                       "in use by another process (it kept the store locked for more "
                       "than %1 s)")
                .arg(kStoreBusyTimeout_ms / 1000);
        case SQLITE_FULL:
            return QStringLiteral("disk full");
        default:
            return {};
    }
}

std::unique_ptr<CampaignStore> CampaignStore::open(const QString& path, StoreAccess access,
                                                   QString* error) {
    if (isServerStoreUrl(path)) return openOnServer(path, access, error);
    QString temporaryPath;
    QSqlDatabase db;
    auto fail = [&](const QString& why) -> std::unique_ptr<CampaignStore> {
        *error = QStringLiteral("%1: %2").arg(path, why);
        if (db.isValid()) {
            const QString name = db.connectionName();
            db.close();
            db = QSqlDatabase();
            QSqlDatabase::removeDatabase(name);
        }
        if (!temporaryPath.isEmpty()) removeWithSideFiles(temporaryPath);
        return nullptr;
    };

    // Everything that decides whether DriftLab may touch the file is read
    // before the first connection that could write to it is opened.
    const QFileInfo file(path);
    StoreFileInfo info;
    QString why;
    if (file.isDir()) return fail(QStringLiteral("a folder, not a DriftLab store"));
    // Inspecting a FIFO would wait for its writer; a device is no database.
    if (const QString kind = bundle::irregularFileKind(path); !kind.isEmpty())
        return fail(kind + QStringLiteral(", not a DriftLab store"));
    if (!file.exists()) {
        if (access != StoreAccess::CreateIfMissing)
            return fail(QStringLiteral("no such DriftLab store"));
        temporaryPath = reserveTemporaryFile(path, &why);
        if (temporaryPath.isEmpty()) return fail(why);
    } else {
        auto inspected = inspectStoreFile(path, &why);
        if (!inspected) return fail(why);
        info = *inspected;
        if (QString r = refusal(info, access); !r.isEmpty()) return fail(r);
        if (QString r = schemaRefusal(info, access); !r.isEmpty()) return fail(r);
    }

    db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), newConnectionName());
    if (access == StoreAccess::ReadOnly) {
        const std::optional<bool> immutable = needsImmutableRead(path, info.walMode, &why);
        if (!immutable) return fail(why);
        db.setConnectOptions(
            QStringLiteral("QSQLITE_OPEN_READONLY;QSQLITE_OPEN_URI;QSQLITE_BUSY_TIMEOUT=%1")
                .arg(kStoreBusyTimeout_ms));
        db.setDatabaseName(sqliteUri(
            path, *immutable ? QStringLiteral("mode=ro&immutable=1") : QStringLiteral("mode=ro")));
        if (!db.open()) return fail(db.lastError().text());
        // SQLite reads the file lazily: this is where an unreadable one says so.
        if (QString e = run(db, QStringLiteral("SELECT count(*) FROM sqlite_schema")); !e.isEmpty())
            return fail(QStringLiteral("cannot be read (%1)").arg(e));
        return std::unique_ptr<CampaignStore>(new CampaignStore(db, path, access, {}));
    }

    // mode=rw: the file exists (inspected, or reserved above); SQLite must not
    // create one, as Qt's read-write open otherwise would.
    db.setConnectOptions(
        QStringLiteral("QSQLITE_OPEN_URI;QSQLITE_BUSY_TIMEOUT=%1").arg(kStoreBusyTimeout_ms));
    db.setDatabaseName(
        sqliteUri(temporaryPath.isEmpty() ? path : temporaryPath, QStringLiteral("mode=rw")));
    if (!db.open()) return fail(db.lastError().text());
    // SQLite falls back to read-only when the file cannot be written.
    if (sqlite3_db_readonly(sqliteHandle(db), "main") != 0)
        return fail(QStringLiteral("cannot be written (no write permission, or read-only media)"));
    // WAL while written: readers never block the logger; NORMAL sync in WAL mode
    // keeps the file consistent on power loss and loses at most the last commits.
    QVariant mode;
    QString e = run(db, QStringLiteral("PRAGMA foreign_keys = ON"));
    if (e.isEmpty()) {
        const QSqlError wal = switchToWal(db, &mode);
        if (isLockedOut(wal))
            return fail(storeWriteCondition(SQLITE_BUSY) +
                        QStringLiteral("; the store is unchanged"));
        if (wal.isValid()) e = wal.text();
    }
    if (e.isEmpty() && mode.toString() != QLatin1String("wal"))
        e = QStringLiteral("journal mode stays '%1'").arg(mode.toString());
    if (e.isEmpty()) e = run(db, QStringLiteral("PRAGMA synchronous = NORMAL"));
    if (e.isEmpty() && info.applicationId != kStoreApplicationId)
        e = run(db, QStringLiteral("PRAGMA application_id = %1").arg(qint32(kStoreApplicationId)));
    if (!e.isEmpty()) return fail(QStringLiteral("not a usable SQLite database (%1)").arg(e));
    if (!migrate(db, &e)) return fail(e);
    return std::unique_ptr<CampaignStore>(new CampaignStore(db, path, access, temporaryPath));
}

void CampaignStore::close() {
    if (!m_db.isValid()) return;
    const QString name = m_db.connectionName();
    if (m_access != StoreAccess::ReadOnly && m_db.isOpen() &&
        backendOf(m_db) == StoreBackend::Sqlite) {
        // Between writers the store rests in rollback-journal mode. In WAL mode
        // every reader needs a -shm beside the file: a read-only connection
        // creates -wal and -shm where it may and leaves them behind (it cannot
        // take the lock that deletes them), and on read-only media it cannot
        // read the file at all. A checkpoint on close empties the WAL but keeps
        // the header in WAL mode, which does not help (both measured, SQLite
        // 3.40). The switch costs the checkpoint the last close does anyway;
        // each open for writing then bumps the header's change counter.
        // busy_timeout 0: while another connection (a reader, the logger) is
        // open SQLite refuses the switch at once and the store stays in WAL, as
        // it must while written; the last writer to close switches it.
        run(m_db, QStringLiteral("PRAGMA busy_timeout = 0"));
        run(m_db, QStringLiteral("PRAGMA journal_mode = DELETE"));
    }
    m_db.close();
    m_db = QSqlDatabase();
    QSqlDatabase::removeDatabase(name);
}

CampaignStore::~CampaignStore() {
    close();
    if (isNew()) removeWithSideFiles(m_temporaryPath);
}

bool CampaignStore::publish(QString* error) {
    close();
    if (!isNew()) return true;
    const QString temporary = std::exchange(m_temporaryPath, QString());
    QString why;
    // Renamed with its WAL still beside it, the store would lose what the WAL holds.
    if (QFileInfo::exists(temporary + QStringLiteral("-wal")))
        why = QStringLiteral(
            "the new store could not be completed: its write-ahead log is "
            "still beside it (a full disk, or the store open elsewhere); "
            "nothing was stored");
    else if (!QFile::rename(temporary, m_path))  // never replaces an existing file
        why = QFileInfo::exists(m_path)
                  ? QStringLiteral("a file appeared there meanwhile; nothing was stored")
                  : QStringLiteral("cannot rename the new store into place");
    if (why.isEmpty()) return true;
    removeWithSideFiles(temporary);
    *error = QStringLiteral("%1: %2").arg(m_path, why);
    return false;
}

std::vector<CampaignSummary> CampaignStore::listCampaigns() const {
    std::vector<CampaignSummary> out;
    QSqlQuery q(m_db);
    q.exec(QStringLiteral(
        "SELECT c.id, c.name, (SELECT count(*) FROM run r WHERE r.campaign_id = c.id), "
        "(SELECT coalesce(sum(b.present_count), 0) FROM sample_block b JOIN run r ON b.run_id = "
        "r.id "
        "WHERE r.campaign_id = c.id) "
        "FROM campaign c ORDER BY c.id"));
    while (q.next())
        out.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toInt(),
                       q.value(3).toLongLong()});
    return out;
}

}  // namespace driftlab::db
