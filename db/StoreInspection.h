#pragma once
// What a file is, found out without changing a byte of it, before DriftLab
// opens it for writing (docs/store.md): a file of another application
// must be refused untouched, and even `PRAGMA journal_mode = WAL` rewrites the
// database header.

#include <QString>
#include <QStringList>
#include <optional>

namespace driftlab::db {

struct StoreFileInfo {
    quint32 applicationId = 0;  ///< PRAGMA application_id
    int userVersion = 0;        ///< PRAGMA user_version: the schema version of a store
    QStringList tables;         ///< the user tables, sorted; empty for an empty database
    bool walMode = false;       ///< the header says WAL (a reader needs a -shm file)
};

/// Reads the header and the table names of an existing file with a read-only
/// connection that creates no -wal/-shm. Returns nullopt and sets `why` (without
/// the path) when the file is not an SQLite database or cannot be read. An empty
/// (0-byte) file is an empty database, as SQLite treats it.
std::optional<StoreFileInfo> inspectStoreFile(const QString& path, QString* why);

/// An SQLite URI naming `path` (made absolute, percent-encoded) with `query`,
/// e.g. "mode=ro"; for connections opened with SQLITE_OPEN_URI.
QString sqliteUri(const QString& path, const QString& query);

/// Whether a read-only connection has to open `path` with `immutable=1`: a
/// WAL-mode file whose folder cannot be written and that has no -shm, where
/// SQLite cannot create the shared-memory file every WAL reader needs. Sets
/// `why` and returns nullopt when the file cannot be read at all that way
/// (committed data left in a -wal that only a writer can recover).
std::optional<bool> needsImmutableRead(const QString& path, bool walMode, QString* why);

}  // namespace driftlab::db
