#pragma once
// Store-and-forward into a server store (docs/lab-store.md, "The spool and
// the upload"). A rig logs into a local SQLite store, its spool, exactly as
// into any store (RunLogger: a kill loses at most the last second); an upload
// pass copies to the server what the spool has committed and the server does
// not have yet. A pass may be cut anywhere (the server goes away, the rig is
// killed) and repeated: each run goes over in one server transaction that
// also records where it came from (upload_origin), sample blocks are keyed by
// (run, first time) and only grow, and rows without a key (readings, motion,
// events) are appended after the ones the server already has. So every
// sample ends up on the server exactly once, however often a pass is cut.

#include <QString>
#include <optional>

#include "db/CampaignStore.h"

namespace driftlab::db {

/// What one upload pass copied.
struct UploadReport {
    int campaigns = 0;    ///< campaigns new on the server
    int runs = 0;         ///< runs new on the server
    qint64 blocks = 0;    ///< sample blocks written (new or grown)
    qint64 rows = 0;      ///< positioning readings, motion segments, events and flags added
    int runsInSpool = 0;  ///< runs the spool holds
    int runsLogging = 0;  ///< of them, still being logged
};

/// The spool's id (a random UUID stored in it on first use; `spool` must be
/// open for writing then). Nullopt with `error` on failure.
std::optional<QString> ensureSpoolId(CampaignStore& spool, QString* error);
/// The id of a spool that has one, else empty.
QString spoolId(CampaignStore& spool);

/// One upload pass from `spool` (read) to `server` (written); nullopt with
/// `error` when it stopped (what it copied before stays copied).
std::optional<UploadReport> uploadSpool(CampaignStore& spool, const QString& spoolId,
                                        CampaignStore& server, QString* error);

/// The server's id of a campaign or run ("campaign" or "run") uploaded from
/// spool `spoolId`, or nullopt when it is not on the server (yet).
std::optional<qint64> uploadedId(CampaignStore& server, const QString& spoolId, const QString& kind,
                                 qint64 spoolRowId);

}  // namespace driftlab::db
