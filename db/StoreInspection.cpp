#include "db/StoreInspection.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <unistd.h>
#include <QFile>
#include <QFileInfo>
#include <QUrl>

#include "db/CampaignStore.h"

namespace driftlab::db {
namespace {

bool isEmptyFile(const QString& path) {
    const QFileInfo info(path);
    return !info.exists() || info.size() == 0;
}

/// Whether this process may create files in the folder of `path` (effective
/// ids; EROFS on read-only media counts as no).
bool folderWritable(const QString& path) {
    const QByteArray folder = QFile::encodeName(QFileInfo(path).absolutePath());
    return faccessat(AT_FDCWD, folder.constData(), W_OK, AT_EACCESS) == 0;
}

}  // namespace

QString sqliteUri(const QString& path, const QString& query) {
    // fromLocalFile percent-encodes '?', '#' and '%', which SQLite decodes again.
    return QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath()).toString(QUrl::FullyEncoded) +
           QLatin1Char('?') + query;
}

std::optional<bool> needsImmutableRead(const QString& path, bool walMode, QString* why) {
    if (!walMode || QFileInfo::exists(path + QStringLiteral("-shm")) || folderWritable(path))
        return false;
    // Every connection to a WAL database keeps its -shm open, so without one no
    // writer is at work, and none can start in a folder nobody may write: the
    // file cannot change while we read it, which is what immutable=1 promises.
    // Where the folder is writable we never do this: a logger may start while
    // we read, and an immutable reader takes no locks against its checkpoints.
    if (!isEmptyFile(path + QStringLiteral("-wal"))) {
        *why = QStringLiteral(
            "its write-ahead log (-wal) holds data that only a writer can bring into the "
            "store, and the folder cannot be written; open the store once for writing");
        return std::nullopt;
    }
    return true;
}

std::optional<StoreFileInfo> inspectStoreFile(const QString& path, QString* why) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = file.errorString();
        return std::nullopt;
    }
    const QByteArray header = file.read(100);
    file.close();
    StoreFileInfo info;
    if (header.isEmpty()) return info;  // SQLite writes into a 0-byte file as into a new one
    static const QByteArray magic("SQLite format 3\0", 16);
    if (header.size() < 100 || !header.startsWith(magic)) {
        *why = QStringLiteral("not an SQLite database");
        return std::nullopt;
    }
    // Bytes 18 and 19: file format write and read versions, 2 in WAL mode.
    info.walMode = header[18] == 2 || header[19] == 2;

    // A WAL-mode file with neither a -shm nor a non-empty -wal is closed by
    // everyone and whole in itself. A plain read-only connection would still
    // create -wal and -shm beside it and, unable to take the write lock a
    // closing connection needs, leave them there (measured with SQLite 3.40),
    // so it is read immutable.
    const bool untouched = !info.walMode || (!QFileInfo::exists(path + QStringLiteral("-shm")) &&
                                             isEmptyFile(path + QStringLiteral("-wal")));
    const QString uri =
        sqliteUri(path, untouched && info.walMode ? QStringLiteral("mode=ro&immutable=1")
                                                  : QStringLiteral("mode=ro"));
    sqlite3* handle = nullptr;
    int rc = sqlite3_open_v2(uri.toUtf8().constData(), &handle,
                             SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
    auto read = [&](const char* sql, auto&& row) {
        sqlite3_stmt* statement = nullptr;
        if (rc == SQLITE_OK) rc = sqlite3_prepare_v2(handle, sql, -1, &statement, nullptr);
        while (rc == SQLITE_OK || rc == SQLITE_ROW) {
            rc = sqlite3_step(statement);
            if (rc == SQLITE_ROW) row(statement);
        }
        if (rc == SQLITE_DONE) rc = SQLITE_OK;
        sqlite3_finalize(statement);
    };
    if (rc == SQLITE_OK) sqlite3_busy_timeout(handle, kStoreBusyTimeout_ms);
    read("PRAGMA application_id",
         [&](sqlite3_stmt* s) { info.applicationId = quint32(sqlite3_column_int(s, 0)); });
    read("PRAGMA user_version",
         [&](sqlite3_stmt* s) { info.userVersion = sqlite3_column_int(s, 0); });
    read(
        "SELECT name FROM sqlite_schema WHERE type = 'table' AND name NOT LIKE 'sqlite\\_%' "
        "ESCAPE '\\' ORDER BY name",
        [&](sqlite3_stmt* s) {
            info.tables << QString::fromUtf8(
                reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
        });
    if (rc != SQLITE_OK) {
        *why =
            rc == SQLITE_NOTADB
                ? QStringLiteral("not an SQLite database")
                : QStringLiteral("cannot be read (%1)")
                      .arg(QString::fromUtf8(handle ? sqlite3_errmsg(handle) : sqlite3_errstr(rc)));
        sqlite3_close(handle);
        return std::nullopt;
    }
    sqlite3_close(handle);
    return info;
}

}  // namespace driftlab::db
