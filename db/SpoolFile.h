#pragma once
// The spool file of a rig that logs into a server store (docs/lab-store.md,
// "The spool and the upload"): where it is by default, making it ready, what
// it holds that the server lacks, and a whole sync pass. Shared by the CLI
// (`run --db postgresql://…`, `sync`) and the desktop application's
// File → Open lab store….

#include <QString>
#include <optional>

#include "db/CampaignStore.h"
#include "db/SpoolUpload.h"

namespace driftlab::db {

/// driftlab/spool.sqlite in the user's data folder ($XDG_DATA_HOME, usually
/// ~/.local/share), its folder created; empty with `error` when it cannot be.
QString defaultSpoolPath(QString* error);

/// Creates the spool when missing, migrates it, and returns its id; nullopt
/// with `error` on failure.
std::optional<QString> prepareSpool(const QString& path, QString* error);

/// What a spool holds against a server store.
struct SpoolState {
    int runs = 0;     ///< runs in the spool
    int pending = 0;  ///< of them, not on the server yet
    int logging = 0;  ///< of them, still being logged
};
/// The state of the spool at `path` (read-only; a spool never uploaded
/// holds only pending runs); nullopt with `error` when it cannot be read.
std::optional<SpoolState> spoolState(const QString& path, CampaignStore& server, QString* error);

/// One sync: the spool made ready, runs whose logger died (crash, kill,
/// power loss) marked interrupted, then one upload pass to `server`.
std::optional<UploadReport> syncSpool(const QString& path, CampaignStore& server, QString* error);

}  // namespace driftlab::db
