#pragma once
// Versioned schema: migration N lifts a database from user_version N-1 to N.
// Migrations are SQL files compiled into the library (migrations/*.sql), each
// applied in its own transaction, so a database written by an older build
// opens in a newer one.

#include <QSqlDatabase>
#include <QString>

namespace driftlab::db {

/// The schema version this build writes.
int latestSchemaVersion();
/// The oldest schema a read-only connection reads without migrating: v3, where
/// samples moved into blocks (sample_block) and campaigns got their content
/// hash. Older stores must be opened for writing once, which migrates them.
int oldestReadableSchemaVersion();
/// PRAGMA user_version of an open database.
int schemaVersion(QSqlDatabase& db);
/// Applies the migrations after the current version up to `target` (default: latest).
/// Returns false and sets `error` if one fails; that migration is rolled back.
bool migrate(QSqlDatabase& db, QString* error, int target = -1);

}  // namespace driftlab::db
