#pragma once
// Sensor samples are stored in blocks: up to kRowsPerBlock consecutive sample
// times of one run, all of the campaign's sample columns, in one BLOB. A row
// per value (run, t, channel, value) costs SQLite a B-tree insert per value
// and cannot reach the import and logging rates of docs/benchmarks.md; a
// block is one insert per few thousand rows, and a run reads back with a copy.
//
// BLOB layout (float64, little-endian): row_count times, then for each sample
// column in channel.column_ordinal order its row_count values; NaN is a
// missing sample. Column-major, so one channel over a time range is one
// contiguous slice (what live plots and per-channel queries read). The same
// bytes are a BLOB on SQLite and a BYTEA on PostgreSQL.

#include <sqlite3.h>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QString>
#include <optional>
#include <vector>

#include "core/domain/Run.h"
#include "db/SqliteStatement.h"

namespace driftlab::db {

constexpr std::size_t kRowsPerBlock = 2048;

/// Collects rows of several runs (rows of a run in increasing time, runs in
/// any interleaving) and writes full blocks as they fill. Throws QString on a
/// database error.
class SampleBlockWriter {
public:
    SampleBlockWriter(sqlite3* handle, std::size_t columnCount, std::vector<qint64> runIds);
    /// Into the store's connection: through the sqlite3 C API on SQLite (the
    /// hot path), through Qt SQL on a server.
    SampleBlockWriter(QSqlDatabase& db, std::size_t columnCount, std::vector<qint64> runIds);

    void append(std::size_t runIndex, double time_s, const double* values);
    /// Writes every partly filled block.
    void flush();

private:
    struct Pending {
        std::vector<double> time_s;
        std::vector<double> values;  ///< kRowsPerBlock per column, column-major
        qint64 present = 0;
    };
    void write(std::size_t runIndex);

    SqliteStatement m_insert;
    std::optional<QSqlQuery> m_serverInsert;  ///< set when the store is not SQLite
    std::size_t m_columns;
    std::vector<qint64> m_runIds;
    std::vector<Pending> m_pending;
    std::vector<double> m_blob;
};

/// Runs `insert` (INSERT [OR REPLACE] INTO sample_block with its seven
/// columns in table order) for one block of `rows` rows: column k's values
/// start at values + k·stride. `scratch` holds the BLOB. Throws QString.
void writeSampleBlock(SqliteStatement& insert, qint64 runId, const double* time_s, std::size_t rows,
                      const double* values, std::size_t stride, std::size_t columns, qint64 present,
                      std::vector<double>& scratch);

/// The BLOB of one block: times, then each column (see the layout above).
void packSampleBlock(const double* time_s, std::size_t rows, const double* values,
                     std::size_t stride, std::size_t columns, std::vector<double>& blob);

/// Reads the samples of a run in time order into `series`, whose `columns`
/// are set; throws QString on a database error or a malformed block.
void loadSampleBlocks(sqlite3* handle, qint64 runId, SampleSeries& series);
/// The same from any store connection (Qt SQL where it is not SQLite).
void loadSampleBlocks(const QSqlDatabase& db, qint64 runId, SampleSeries& series);

/// Schema v2 → v3: moves the rows of the old one-value-per-row `sample` table
/// into blocks and drops it. Runs inside the migration's transaction; throws
/// QString on failure.
void moveSampleRowsIntoBlocks(sqlite3* handle);

}  // namespace driftlab::db
