#include "db/SampleBlocks.h"

#include <QtEndian>
#include <cmath>
#include <cstring>
#include <memory>

namespace driftlab::db {
namespace {

static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN,
              "sample blocks are float64 little-endian; add byte swapping for this platform");

QString sqliteError(sqlite3* handle) {
    return QString::fromUtf8(sqlite3_errmsg(handle));
}

}  // namespace

SampleBlockWriter::SampleBlockWriter(sqlite3* handle, std::size_t columnCount,
                                     std::vector<qint64> runIds)
    : m_handle(handle),
      m_columns(columnCount),
      m_runIds(std::move(runIds)),
      m_pending(m_runIds.size()) {
    if (sqlite3_prepare_v2(handle,
                           "INSERT INTO sample_block (run_id, first_t, last_t, row_count, "
                           "column_count, present_count, data) VALUES (?, ?, ?, ?, ?, ?, ?)",
                           -1, &m_insert, nullptr) != SQLITE_OK)
        throw sqliteError(handle);
}

SampleBlockWriter::~SampleBlockWriter() {
    sqlite3_finalize(m_insert);
}

void SampleBlockWriter::append(std::size_t runIndex, double time_s, const double* values) {
    Pending& p = m_pending[runIndex];
    if (p.values.empty()) p.values.resize(kRowsPerBlock * m_columns);
    const std::size_t row = p.time_s.size();
    p.time_s.push_back(time_s);
    for (std::size_t k = 0; k < m_columns; ++k) {
        p.values[k * kRowsPerBlock + row] = values[k];
        p.present += !std::isnan(values[k]);
    }
    if (p.time_s.size() == kRowsPerBlock) write(runIndex);
}

void SampleBlockWriter::flush() {
    for (std::size_t r = 0; r < m_pending.size(); ++r)
        if (!m_pending[r].time_s.empty()) write(r);
}

void SampleBlockWriter::write(std::size_t runIndex) {
    Pending& p = m_pending[runIndex];
    const std::size_t rows = p.time_s.size();
    m_blob.resize(rows * (m_columns + 1));
    std::memcpy(m_blob.data(), p.time_s.data(), rows * sizeof(double));
    for (std::size_t k = 0; k < m_columns; ++k)
        std::memcpy(m_blob.data() + (k + 1) * rows, p.values.data() + k * kRowsPerBlock,
                    rows * sizeof(double));
    sqlite3_bind_int64(m_insert, 1, m_runIds[runIndex]);
    sqlite3_bind_double(m_insert, 2, p.time_s.front());
    sqlite3_bind_double(m_insert, 3, p.time_s.back());
    sqlite3_bind_int64(m_insert, 4, qint64(rows));
    sqlite3_bind_int64(m_insert, 5, qint64(m_columns));
    sqlite3_bind_int64(m_insert, 6, p.present);
    sqlite3_bind_blob64(m_insert, 7, m_blob.data(), m_blob.size() * sizeof(double), SQLITE_STATIC);
    const int rc = sqlite3_step(m_insert);
    sqlite3_reset(m_insert);
    if (rc != SQLITE_DONE) throw sqliteError(m_handle);
    p.time_s.clear();
    p.present = 0;
}

void loadSampleBlocks(sqlite3* handle, qint64 runId, SampleSeries& s) {
    sqlite3_stmt* q = nullptr;
    if (sqlite3_prepare_v2(handle,
                           "SELECT row_count, column_count, data FROM sample_block "
                           "WHERE run_id = ? ORDER BY first_t",
                           -1, &q, nullptr) != SQLITE_OK)
        throw sqliteError(handle);
    sqlite3_bind_int64(q, 1, runId);
    const std::size_t columns = s.columns.size();
    s.values.assign(columns, {});
    int rc;
    while ((rc = sqlite3_step(q)) == SQLITE_ROW) {
        const auto rows = std::size_t(sqlite3_column_int64(q, 0));
        const auto stored = std::size_t(sqlite3_column_int64(q, 1));
        const auto* data = static_cast<const char*>(sqlite3_column_blob(q, 2));
        const auto bytes = std::size_t(sqlite3_column_bytes(q, 2));
        if (stored != columns || bytes != rows * (columns + 1) * sizeof(double)) {
            sqlite3_finalize(q);
            throw QStringLiteral(
                "run %1: a sample block of %2 bytes does not hold %3 rows of %4 "
                "columns (damaged store?)")
                .arg(runId)
                .arg(bytes)
                .arg(rows)
                .arg(columns);
        }
        auto append = [&](std::vector<double>& to, std::size_t slice) {
            const std::size_t old = to.size();
            to.resize(old + rows);
            std::memcpy(to.data() + old, data + slice * rows * sizeof(double),
                        rows * sizeof(double));
        };
        append(s.time_s, 0);
        for (std::size_t k = 0; k < columns; ++k) append(s.values[k], k + 1);
    }
    sqlite3_finalize(q);
    if (rc != SQLITE_DONE) throw sqliteError(handle);
}

}  // namespace driftlab::db

namespace driftlab::db {

void moveSampleRowsIntoBlocks(sqlite3* handle) {
    auto prepare = [&](const char* sql) {
        sqlite3_stmt* statement = nullptr;
        if (sqlite3_prepare_v2(handle, sql, -1, &statement, nullptr) != SQLITE_OK)
            throw sqliteError(handle);
        return std::unique_ptr<sqlite3_stmt, int (*)(sqlite3_stmt*)>(statement, sqlite3_finalize);
    };
    auto runs = prepare(
        "SELECT r.id, (SELECT count(*) FROM channel c WHERE c.campaign_id = r.campaign_id "
        "AND c.column_ordinal IS NOT NULL) FROM run r ORDER BY r.id");
    auto rows = prepare(
        "SELECT s.t, c.column_ordinal, s.value FROM sample s JOIN channel c ON c.id = s.channel_id "
        "WHERE s.run_id = ? ORDER BY s.t");
    while (sqlite3_step(runs.get()) == SQLITE_ROW) {
        const qint64 runId = sqlite3_column_int64(runs.get(), 0);
        const auto columns = std::size_t(sqlite3_column_int64(runs.get(), 1));
        SampleBlockWriter writer(handle, columns, {runId});
        std::vector<double> row(columns, std::nan(""));
        double t = 0;
        bool open = false;
        sqlite3_bind_int64(rows.get(), 1, runId);
        int rc;
        while ((rc = sqlite3_step(rows.get())) == SQLITE_ROW) {
            const double rowTime = sqlite3_column_double(rows.get(), 0);
            if (open && rowTime != t) {
                writer.append(0, t, row.data());
                std::fill(row.begin(), row.end(), std::nan(""));
            }
            t = rowTime;
            open = true;
            const auto column = std::size_t(sqlite3_column_int64(rows.get(), 1));
            if (column < columns) row[column] = sqlite3_column_double(rows.get(), 2);
        }
        if (rc != SQLITE_DONE) throw sqliteError(handle);
        if (open) writer.append(0, t, row.data());
        writer.flush();
        sqlite3_reset(rows.get());
    }
    if (sqlite3_exec(handle, "DROP TABLE sample", nullptr, nullptr, nullptr) != SQLITE_OK)
        throw sqliteError(handle);
}

}  // namespace driftlab::db
