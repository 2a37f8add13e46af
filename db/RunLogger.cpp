#include "db/RunLogger.h"

#include <QFileInfo>
#include <QSqlError>
#include <QSqlQuery>
#include <cmath>

#include "db/SqlValues.h"

namespace driftlab::db {
namespace {

/// Runs SQL on the logger's connection; throws QString on failure.
void exec(sqlite3* handle, const char* sql) {
    char* message = nullptr;
    if (sqlite3_exec(handle, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        const QString why = QString::fromUtf8(message ? message : "unknown error");
        sqlite3_free(message);
        throw why;
    }
}

QSqlQuery prepared(QSqlDatabase& db, const QString& sql, const QVariantList& values) {
    QSqlQuery q(db);
    if (!q.prepare(sql)) throw q.lastError().text();
    for (const QVariant& v : values) q.addBindValue(v);
    if (!q.exec()) throw q.lastError().text();
    return q;
}

bool failWith(QString* error, const QString& why) {
    if (error) *error = why;
    return false;
}

/// Live logging uses the sqlite3 C API (one synchronous commit a second); a
/// server store gets its runs through the spool and the uploader instead.
bool refuseServerStore(CampaignStore& store, QString* error) {
    if (!store.isServer()) return false;
    failWith(error, QStringLiteral("%1: runs are logged into a local SQLite spool and uploaded "
                                   "to a server store (docs/lab-store.md), not logged into it")
                        .arg(store.path()));
    return true;
}

}  // namespace

double LoggedRunState::end_s() const {
    return std::max(last_sample_s.value_or(0), last_reading_s.value_or(0));
}

QString RunLogger::lockPath(const QString& storePath, qint64 runId) {
    return QStringLiteral("%1.run-%2.lock").arg(QFileInfo(storePath).absoluteFilePath()).arg(runId);
}

RunLogger::RunLogger(CampaignStore& store, qint64 runId, std::size_t columns)
    : m_store(store), m_runId(runId), m_columns(columns), m_lock(lockPath(store.path(), runId)) {
    m_lock.setStaleLockTime(0);  // only a dead owner makes a lock stale
    m_block.values.resize(kRowsPerBlock * m_columns);
}

bool RunLogger::start(QString* error) {
    if (!m_lock.tryLock(0))
        return failWith(error, QStringLiteral("run %1 is being logged by another process (%2)")
                                   .arg(m_runId)
                                   .arg(m_lock.fileName()));
    sqlite3* handle = sqliteHandle(m_store.database());
    try {
        // One fsync per commit (a second apart): a power loss keeps what was committed.
        exec(handle, "PRAGMA synchronous = FULL");
        m_insertBlock = std::make_unique<SqliteStatement>(
            handle,
            "INSERT OR REPLACE INTO sample_block (run_id, first_t, last_t, row_count, "
            "column_count, present_count, data) VALUES (?, ?, ?, ?, ?, ?, ?)");
        m_insertReading = std::make_unique<SqliteStatement>(
            handle, "INSERT INTO positioning VALUES (?, ?, ?, ?, ?, ?)");
        m_insertMotion = std::make_unique<SqliteStatement>(
            handle, "INSERT INTO motion_segment VALUES (?, ?, ?, ?, ?, ?)");
        for (auto* s : {m_insertBlock.get(), m_insertReading.get(), m_insertMotion.get()})
            if (!s->ok()) throw s->error();
        prepared(m_store.database(),
                 QStringLiteral("UPDATE run SET status = 'logging' WHERE id = ?"), {m_runId});
    } catch (const QString& why) {
        return failWith(error, QStringLiteral("run %1: %2").arg(m_runId).arg(why));
    }
    m_sinceCommit.start();
    return true;
}

std::unique_ptr<RunLogger> RunLogger::begin(CampaignStore& store, qint64 campaignId,
                                            const RunHeader& h, QString* error) {
    if (refuseServerStore(store, error)) return nullptr;
    QSqlDatabase& db = store.database();
    qint64 runId = 0;
    std::size_t columns = 0;
    try {
        columns = sampleColumns(store, campaignId).size();
        QSqlQuery ordinal = prepared(
            db,
            QStringLiteral("SELECT coalesce(max(ordinal) + 1, 0) FROM run WHERE campaign_id = ?"),
            {campaignId});
        ordinal.next();
        QSqlQuery insert = prepared(
            db,
            QStringLiteral("INSERT INTO run (campaign_id, name, ordinal, kind, feed_mm_min, "
                           "range_from_mm, range_to_mm, description, extra_json, status) "
                           "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, 'logging')"),
            {campaignId, h.name, ordinal.value(0), toString(h.kind), toSql(h.feed_mm_min),
             toSql(h.range_mm ? std::optional(h.range_mm->from_mm) : std::nullopt),
             toSql(h.range_mm ? std::optional(h.range_mm->to_mm) : std::nullopt),
             text(h.description), jsonText(h.extra)});
        runId = insert.lastInsertId().toLongLong();
    } catch (const QString& why) {
        failWith(error, QStringLiteral("run %1: cannot be added: %2").arg(h.name, why));
        return nullptr;
    }
    std::unique_ptr<RunLogger> logger(new RunLogger(store, runId, columns));
    if (!logger->start(error)) return nullptr;
    return logger;
}

std::unique_ptr<RunLogger> RunLogger::resume(CampaignStore& store, qint64 runId, QString* error) {
    if (refuseServerStore(store, error)) return nullptr;
    const auto state = loggedRunState(store, runId, error);
    if (!state) return nullptr;
    if (state->status == QLatin1String("complete")) {
        failWith(error, QStringLiteral("run %1 (%2) is complete; there is nothing to resume")
                            .arg(runId)
                            .arg(state->name));
        return nullptr;
    }
    std::unique_ptr<RunLogger> logger(
        new RunLogger(store, runId, sampleColumns(store, state->campaign_id).size()));
    if (!logger->start(error)) return nullptr;
    logger->m_lastTime_s = state->last_sample_s;
    logger->m_rows = logger->m_savedRows = state->rows;
    logger->m_savedUntil_s = state->last_sample_s;
    logger->appendEvent(QStringLiteral("info"), QStringLiteral("logger"),
                        QStringLiteral("resumed after %1 s").arg(state->end_s()));
    return logger;
}

RunLogger::~RunLogger() {
    if (!m_finished) finish(QStringLiteral("interrupted"), nullptr);
}

void RunLogger::appendRow(double time_s, const double* values) {
    const std::size_t row = m_block.time_s.size();
    m_block.time_s.push_back(time_s);
    for (std::size_t k = 0; k < m_columns; ++k) {
        m_block.values[k * kRowsPerBlock + row] = values[k];
        m_block.present += !std::isnan(values[k]);
    }
    m_blockDirty = true;
    m_lastTime_s = time_s;
    ++m_rows;
    if (m_block.time_s.size() == kRowsPerBlock) {
        m_fullBlocks.push_back(std::move(m_block));
        m_block = {};
        m_block.values.resize(kRowsPerBlock * m_columns);
        m_blockDirty = false;
    }
}

void RunLogger::appendReading(const PositioningMeasurement& reading) {
    m_readings.push_back(reading);
}
void RunLogger::appendMotion(const MotionSegment& segment) {
    m_motion.push_back(segment);
}
void RunLogger::appendEvent(const QString& level, const QString& source, const QString& message) {
    m_events.push_back({level, source, message});
}

// A full block replaces the partial one written at earlier commits (same
// run and first time); the block being filled is rewritten at each commit.
void RunLogger::writePending() {
    auto write = [&](const Block& b) {
        writeSampleBlock(*m_insertBlock, m_runId, b.time_s.data(), b.time_s.size(), b.values.data(),
                         kRowsPerBlock, m_columns, b.present, m_blob);
    };
    for (const Block& b : m_fullBlocks) write(b);
    if (m_blockDirty) write(m_block);
    for (const PositioningMeasurement& p : m_readings) {
        m_insertReading->bind(1, m_runId);
        m_insertReading->bind(2, p.time_s);
        m_insertReading->bind(3, qint64(p.cycle));
        m_insertReading->bind(4, p.target_mm);
        sqlite3_bind_text(m_insertReading->get(), 5, p.direction == Direction::Positive ? "+" : "-",
                          1, SQLITE_STATIC);
        m_insertReading->bind(6, p.deviation_um);
        if (!m_insertReading->execute()) throw m_insertReading->error();
    }
    for (const MotionSegment& m : m_motion) {
        m_insertMotion->bind(1, m_runId);
        m_insertMotion->bind(2, m.start_s);
        m_insertMotion->bind(3, m.end_s);
        m_insertMotion->bind(4, m.from_mm);
        m_insertMotion->bind(5, m.to_mm);
        m_insertMotion->bind(6, m.feed_mm_min);
        if (!m_insertMotion->execute()) throw m_insertMotion->error();
    }
    for (const Event& e : m_events)
        prepared(m_store.database(),
                 QStringLiteral("INSERT INTO event_log (campaign_id, run_id, level, source, "
                                "message) SELECT campaign_id, id, ?, ?, ? FROM run WHERE id = ?"),
                 {e.level, e.source, e.message, m_runId});
}

bool RunLogger::commit(QString* error) {
    sqlite3* handle = sqliteHandle(m_store.database());
    try {
        exec(handle, "BEGIN IMMEDIATE");
        try {
            writePending();
            exec(handle, "COMMIT");
        } catch (const QString&) {
            sqlite3_exec(handle, "ROLLBACK", nullptr, nullptr, nullptr);
            throw;
        }
    } catch (const QString& why) {
        return failWith(error, QStringLiteral("%1: run %2: the store refuses the rows: %3")
                                   .arg(m_store.path())
                                   .arg(m_runId)
                                   .arg(why));
    }
    m_fullBlocks.clear();
    m_blockDirty = false;
    m_savedRows = m_rows;
    m_savedUntil_s = m_lastTime_s;
    m_readings.clear();
    m_motion.clear();
    m_events.clear();
    m_sinceCommit.restart();
    return true;
}

bool RunLogger::commitIfDue(QString* error, int interval_ms) {
    return m_sinceCommit.elapsed() < interval_ms || commit(error);
}

bool RunLogger::finish(const QString& status, QString* error) {
    if (m_finished) return true;
    bool ok = commit(error);
    if (ok) {
        try {
            prepared(m_store.database(), QStringLiteral("UPDATE run SET status = ? WHERE id = ?"),
                     {status, m_runId});
        } catch (const QString& why) {
            ok =
                failWith(error, QStringLiteral("run %1: status not set: %2").arg(m_runId).arg(why));
        }
    }
    m_finished = true;
    m_lock.unlock();
    return ok;
}

}  // namespace driftlab::db
