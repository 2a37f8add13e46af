#pragma once
// The campaign store: one SQLite file (WAL while written, foreign keys on)
// holding campaigns, their runs and data, and what DriftLab derives from them
// (docs/store.md). It marks itself with an application_id, never writes
// into another application's file, and is read with read-only connections by
// the commands that only read. The same store can live in a database on a
// PostgreSQL server, named by a postgresql://USER@HOST[:PORT]/DB URL (the
// lab's shared store, docs/lab-store.md): same schema version, marked by a
// driftlab_store table (ServerStore.cpp).

#include <QSqlDatabase>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"

namespace driftlab::db {

/// SQLite `PRAGMA application_id` of a DriftLab store: "DRFT" in ASCII. Written
/// when a store is created or opened for writing (a store of the builds before
/// it, id 0, is stamped then); DriftLab writes into no file with another id.
inline constexpr quint32 kStoreApplicationId = 0x44524654;

/// How long a command waits for another process's lock on a SQLite store (SQLite's
/// busy timeout, and the wait for a change of journal mode) before it gives up.
inline constexpr int kStoreBusyTimeout_ms = 5000;

/// What an SQLite result code (primary or extended) of a failed write means to
/// the user, where it means more than SQLite's text: "in use by another process
/// (…)" for a store another process kept locked past kStoreBusyTimeout_ms,
/// "disk full" for a full disk or quota; empty for any other code.
QString storeWriteCondition(int sqliteResultCode);

/// How a store is opened.
enum class StoreAccess {
    /// An existing store, read with SQLite's read-only flags: never created,
    /// migrated or stamped; works on read-only media and leaves no -wal/-shm.
    ReadOnly,
    /// An existing store to write into (a missing file is an error), migrated
    /// to this build's schema and stamped with kStoreApplicationId.
    ReadWrite,
    /// As ReadWrite, but a missing file is created: built under a temporary
    /// name in the same folder, renamed to its path only by publish().
    CreateIfMissing,
};

struct CampaignSummary {
    qint64 id = 0;
    QString name;
    int runs = 0;
    qint64 samples = 0;  ///< present sample values over all runs and channels
};

class CampaignStore {
public:
    /// Opens the store at `path` as `access` says, after checking read-only that
    /// the file is a DriftLab store (or, for writing, an empty database). Returns
    /// nullptr and sets `error` ("PATH: why") on failure; the file is then untouched.
    /// A postgresql:// URL opens a server store: its database must exist (the
    /// server's administrator creates it); an empty one becomes a store when
    /// opened for writing, one holding anything else is refused.
    static std::unique_ptr<CampaignStore> open(const QString& path, StoreAccess access,
                                               QString* error);
    /// Closes the store; a new store that was not published is deleted.
    ~CampaignStore();
    CampaignStore(const CampaignStore&) = delete;
    CampaignStore& operator=(const CampaignStore&) = delete;

    /// Stores a whole campaign in one transaction: on any error (or when
    /// `progress` returns false) nothing is stored. Returns the campaign id.
    /// `beforeCommit` (given the new id) writes what must be stored with the
    /// campaign in the same transaction; it throws QString to refuse.
    std::optional<qint64> importCampaign(
        const Campaign& campaign, QString* error, const std::function<bool(double)>& progress = {},
        const std::function<void(qint64 campaignId)>& beforeCommit = {});
    /// Reads a campaign back exactly as it was imported.
    std::optional<Campaign> loadCampaign(qint64 id, QString* error) const;
    std::vector<CampaignSummary> listCampaigns() const;

    /// Closes the store and, when it is new (CreateIfMissing on a missing file),
    /// renames it from its temporary name to path(). False with `error` when that
    /// fails (a file appeared at the path meanwhile); the new store is then deleted.
    /// The store cannot be used afterwards.
    bool publish(QString* error);
    /// Whether this store was created by open() and is not yet at path().
    bool isNew() const { return !m_temporaryPath.isEmpty(); }

    QSqlDatabase& database() { return m_db; }
    /// The path the store was opened with (also for a new one not yet published).
    QString path() const { return m_path; }
    StoreAccess access() const { return m_access; }
    /// Whether the store is on a PostgreSQL server rather than in a SQLite file.
    bool isServer() const;

private:
    CampaignStore(QSqlDatabase db, QString path, StoreAccess access, QString temporaryPath)
        : m_db(std::move(db)),
          m_path(std::move(path)),
          m_access(access),
          m_temporaryPath(std::move(temporaryPath)) {}
    static std::unique_ptr<CampaignStore> openOnServer(const QString& url, StoreAccess access,
                                                       QString* error);
    void close();

    QSqlDatabase m_db;
    QString m_path;
    StoreAccess m_access;
    QString m_temporaryPath;  ///< where a new store is built until publish()
};

}  // namespace driftlab::db
