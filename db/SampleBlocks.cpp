#include "db/SampleBlocks.h"

#include <QSqlError>
#include <QtEndian>
#include <cmath>
#include <cstring>

namespace driftlab::db {
namespace {

const char* const kInsertSql =
    "INSERT INTO sample_block (run_id, first_t, last_t, row_count, column_count, "
    "present_count, data) VALUES (?, ?, ?, ?, ?, ?, ?)";

/// Appends one stored block to `s` after checking that its size fits its shape.
void appendBlock(qint64 runId, std::size_t rows, std::size_t stored, const char* data,
                 std::size_t bytes, SampleSeries& s) {
    const std::size_t columns = s.columns.size();
    if (stored != columns || bytes != rows * (columns + 1) * sizeof(double))
        throw QStringLiteral(
            "run %1: a sample block of %2 bytes does not hold %3 rows of %4 "
            "columns (damaged store?)")
            .arg(runId)
            .arg(bytes)
            .arg(rows)
            .arg(columns);
    auto append = [&](std::vector<double>& to, std::size_t slice) {
        const std::size_t old = to.size();
        to.resize(old + rows);
        std::memcpy(to.data() + old, data + slice * rows * sizeof(double), rows * sizeof(double));
    };
    append(s.time_s, 0);
    for (std::size_t k = 0; k < columns; ++k) append(s.values[k], k + 1);
}

}  // namespace

static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN,
              "sample blocks are float64 little-endian; add byte swapping for this platform");

SampleBlockWriter::SampleBlockWriter(sqlite3* handle, std::size_t columnCount,
                                     std::vector<qint64> runIds)
    : m_insert(handle, kInsertSql),
      m_columns(columnCount),
      m_runIds(std::move(runIds)),
      m_pending(m_runIds.size()) {
    if (!m_insert.ok()) throw m_insert.error();
}

SampleBlockWriter::SampleBlockWriter(QSqlDatabase& db, std::size_t columnCount,
                                     std::vector<qint64> runIds)
    : m_insert(sqliteHandle(db), kInsertSql),
      m_columns(columnCount),
      m_runIds(std::move(runIds)),
      m_pending(m_runIds.size()) {
    if (sqliteHandle(db)) {
        if (!m_insert.ok()) throw m_insert.error();
        return;
    }
    m_serverInsert.emplace(db);
    if (!m_serverInsert->prepare(QString::fromLatin1(kInsertSql)))
        throw m_serverInsert->lastError().text();
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
    if (m_serverInsert) {
        const std::size_t rows = p.time_s.size();
        packSampleBlock(p.time_s.data(), rows, p.values.data(), kRowsPerBlock, m_columns, m_blob);
        QSqlQuery& q = *m_serverInsert;
        q.bindValue(0, m_runIds[runIndex]);
        q.bindValue(1, p.time_s.front());
        q.bindValue(2, p.time_s.back());
        q.bindValue(3, qint64(rows));
        q.bindValue(4, qint64(m_columns));
        q.bindValue(5, p.present);
        q.bindValue(6, QByteArray(reinterpret_cast<const char*>(m_blob.data()),
                                  qsizetype(m_blob.size() * sizeof(double))));
        if (!q.exec()) throw q.lastError().text();
    } else {
        writeSampleBlock(m_insert, m_runIds[runIndex], p.time_s.data(), p.time_s.size(),
                         p.values.data(), kRowsPerBlock, m_columns, p.present, m_blob);
    }
    p.time_s.clear();
    p.present = 0;
}

void packSampleBlock(const double* time_s, std::size_t rows, const double* values,
                     std::size_t stride, std::size_t columns, std::vector<double>& blob) {
    blob.resize(rows * (columns + 1));
    std::memcpy(blob.data(), time_s, rows * sizeof(double));
    for (std::size_t k = 0; k < columns; ++k)
        std::memcpy(blob.data() + (k + 1) * rows, values + k * stride, rows * sizeof(double));
}

void writeSampleBlock(SqliteStatement& insert, qint64 runId, const double* time_s, std::size_t rows,
                      const double* values, std::size_t stride, std::size_t columns, qint64 present,
                      std::vector<double>& blob) {
    packSampleBlock(time_s, rows, values, stride, columns, blob);
    insert.bind(1, runId);
    insert.bind(2, time_s[0]);
    insert.bind(3, time_s[rows - 1]);
    insert.bind(4, qint64(rows));
    insert.bind(5, qint64(columns));
    insert.bind(6, present);
    insert.bind(7, blob.data(), blob.size() * sizeof(double));
    if (!insert.execute()) throw insert.error();
}

void loadSampleBlocks(sqlite3* handle, qint64 runId, SampleSeries& s) {
    SqliteStatement q(handle,
                      "SELECT row_count, column_count, data FROM sample_block "
                      "WHERE run_id = ? ORDER BY first_t");
    if (!q.ok()) throw q.error();
    q.bind(1, runId);
    s.values.assign(s.columns.size(), {});
    while (q.nextRow())
        appendBlock(runId, std::size_t(sqlite3_column_int64(q.get(), 0)),
                    std::size_t(sqlite3_column_int64(q.get(), 1)),
                    static_cast<const char*>(sqlite3_column_blob(q.get(), 2)),
                    std::size_t(sqlite3_column_bytes(q.get(), 2)), s);
    if (q.failed()) throw q.error();
}

void loadSampleBlocks(const QSqlDatabase& db, qint64 runId, SampleSeries& s) {
    if (sqlite3* handle = sqliteHandle(db)) return loadSampleBlocks(handle, runId, s);
    QSqlQuery q(db);
    // Streamed (a run's blocks can be large) and read to the end before the
    // next query: Qt's PostgreSQL driver would lose unread rows otherwise.
    q.setForwardOnly(true);
    q.prepare(
        QStringLiteral("SELECT row_count, column_count, data FROM sample_block "
                       "WHERE run_id = ? ORDER BY first_t"));
    q.addBindValue(runId);
    if (!q.exec()) throw q.lastError().text();
    s.values.assign(s.columns.size(), {});
    while (q.next()) {
        const QByteArray data = q.value(2).toByteArray();
        appendBlock(runId, std::size_t(q.value(0).toLongLong()),
                    std::size_t(q.value(1).toLongLong()), data.constData(),
                    std::size_t(data.size()), s);
    }
    if (q.lastError().isValid()) throw q.lastError().text();
}

void moveSampleRowsIntoBlocks(sqlite3* handle) {
    SqliteStatement runs(
        handle,
        "SELECT r.id, (SELECT count(*) FROM channel c WHERE c.campaign_id = "
        "r.campaign_id AND c.column_ordinal IS NOT NULL) FROM run r ORDER BY r.id");
    SqliteStatement rows(handle,
                         "SELECT s.t, c.column_ordinal, s.value FROM sample s JOIN channel c ON "
                         "c.id = s.channel_id WHERE s.run_id = ? ORDER BY s.t");
    if (!runs.ok() || !rows.ok()) throw runs.error();
    while (runs.nextRow()) {
        const qint64 runId = sqlite3_column_int64(runs.get(), 0);
        const auto columns = std::size_t(sqlite3_column_int64(runs.get(), 1));
        SampleBlockWriter writer(handle, columns, {runId});
        std::vector<double> row(columns, std::nan(""));
        double t = 0;
        bool open = false;
        rows.reset();
        rows.bind(1, runId);
        while (rows.nextRow()) {
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
        if (rows.failed()) throw rows.error();
        if (open) writer.append(0, t, row.data());
        writer.flush();
    }
    if (runs.failed()) throw runs.error();
    if (sqlite3_exec(handle, "DROP TABLE sample", nullptr, nullptr, nullptr) != SQLITE_OK)
        throw QString::fromUtf8(sqlite3_errmsg(handle));
}

}  // namespace driftlab::db
