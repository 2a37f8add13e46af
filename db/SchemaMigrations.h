#pragma once
// Versioned schema: migration N lifts a database from schema version N-1 to N.
// Migrations are SQL files compiled into the library (migrations/*.sql, and
// migrations/postgresql/*.sql in PostgreSQL's dialect), each
// applied in its own transaction, so a database written by an older build
// opens in a newer one.

#include <QSqlDatabase>
#include <QString>

#include "db/StoreBackend.h"

namespace driftlab::db {

/// The schema version this build writes.
int latestSchemaVersion();
/// The number of migrations of one back end (the same for both; a test checks).
int latestSchemaVersion(StoreBackend backend);
/// The oldest schema a read-only connection reads without migrating: v3, where
/// samples moved into blocks (sample_block) and campaigns got their content
/// hash. Older stores must be opened for writing once, which migrates them.
int oldestReadableSchemaVersion();
/// The schema version of an open store: PRAGMA user_version on SQLite, the
/// mark's schema_version on a server (-1 when it cannot be read).
int schemaVersion(QSqlDatabase& db);
/// Applies the migrations after the current version up to `target` (default: latest).
/// Returns false and sets `error` if one fails; that migration is rolled back.
bool migrate(QSqlDatabase& db, QString* error, int target = -1);

}  // namespace driftlab::db
