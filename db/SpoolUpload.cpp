#include "db/SpoolUpload.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QUuid>

#include "db/StoreBackend.h"

namespace driftlab::db {
namespace {

/// A prepared statement run with `values`; throws QString on failure.
QSqlQuery exec(QSqlDatabase& db, const QString& sql, const QVariantList& values = {}) {
    QSqlQuery q(db);
    // Not on the server: Qt's PostgreSQL driver streams a forward-only result
    // and loses what is unread when the next query starts (CampaignLoader.cpp).
    q.setForwardOnly(backendOf(db) == StoreBackend::Sqlite);
    if (!q.prepare(sql)) throw q.lastError().text();
    for (const QVariant& v : values) q.addBindValue(v);
    if (!q.exec()) throw q.lastError().text();
    return q;
}

qint64 scalar(QSqlDatabase& db, const QString& sql, const QVariantList& values) {
    QSqlQuery q = exec(db, sql, values);
    return q.next() ? q.value(0).toLongLong() : 0;
}

void recordOrigin(QSqlDatabase& server, const QString& spoolId, const QString& kind,
                  qint64 spoolRowId, qint64 rowId) {
    exec(server,
         QStringLiteral("INSERT INTO upload_origin (spool_id, kind, spool_row_id, row_id) "
                        "VALUES (?, ?, ?, ?)"),
         {spoolId, kind, spoolRowId, rowId});
}

/// Appends the rows of `table` of a spool run after the `n` the server has:
/// rows without a key of their own, in the order they were logged (`order`).
qint64 appendMissingRows(QSqlDatabase& spool, QSqlDatabase& server, const QString& table,
                         const QString& columns, const QString& order, qint64 spoolRun,
                         qint64 serverRun) {
    const qint64 have = scalar(
        server, QStringLiteral("SELECT count(*) FROM %1 WHERE run_id = ?").arg(table), {serverRun});
    QSqlQuery rows =
        exec(spool,
             QStringLiteral("SELECT %1 FROM %2 WHERE run_id = ? ORDER BY %3 LIMIT -1 OFFSET ?")
                 .arg(columns, table, order),
             {spoolRun, have});
    const int n = columns.count(QLatin1Char(',')) + 1;
    QStringList marks;
    for (int k = 0; k < n; ++k) marks << QStringLiteral("?");
    QSqlQuery insert(server);
    if (!insert.prepare(QStringLiteral("INSERT INTO %1 (run_id, %2) VALUES (?, %3)")
                            .arg(table, columns, marks.join(QStringLiteral(", ")))))
        throw insert.lastError().text();
    qint64 added = 0;
    while (rows.next()) {
        insert.bindValue(0, serverRun);
        for (int k = 0; k < n; ++k) insert.bindValue(k + 1, rows.value(k));
        if (!insert.exec()) throw insert.lastError().text();
        ++added;
    }
    return added;
}

/// The blocks of a spool run the server lacks or holds shorter (the last one
/// grows while the run is logged). Returns how many were written.
qint64 upsertBlocks(QSqlDatabase& spool, QSqlDatabase& server, qint64 spoolRun, qint64 serverRun) {
    // Blocks before the server's last one are full and already there.
    QSqlQuery last = exec(server,
                          QStringLiteral("SELECT max(first_t) FROM sample_block WHERE "
                                         "run_id = ?"),
                          {serverRun});
    const QVariant from = last.next() ? last.value(0) : QVariant();
    QSqlQuery blocks =
        exec(spool,
             QStringLiteral("SELECT first_t, last_t, row_count, column_count, present_count, data "
                            "FROM sample_block WHERE run_id = ? AND first_t >= ? ORDER BY first_t"),
             {spoolRun, from.isNull() ? QVariant(-1e300) : QVariant(from.toDouble())});
    QSqlQuery upsert(server);
    if (!upsert.prepare(QStringLiteral(
            "INSERT INTO sample_block (run_id, first_t, last_t, row_count, column_count, "
            "present_count, data) VALUES (?, ?, ?, ?, ?, ?, ?) "
            "ON CONFLICT (run_id, first_t) DO UPDATE SET last_t = excluded.last_t, "
            "row_count = excluded.row_count, present_count = excluded.present_count, "
            "data = excluded.data WHERE sample_block.row_count < excluded.row_count")))
        throw upsert.lastError().text();
    qint64 written = 0;
    while (blocks.next()) {
        upsert.bindValue(0, serverRun);
        for (int k = 0; k < 6; ++k) upsert.bindValue(k + 1, blocks.value(k));
        if (!upsert.exec()) throw upsert.lastError().text();
        written += upsert.numRowsAffected() > 0;
    }
    return written;
}

/// Replaces the server's flags of a run when the spool's differ in number
/// (flags are recomputed as a whole, db/SampleFlagStore.h).
qint64 copyFlags(QSqlDatabase& spool, QSqlDatabase& server, qint64 spoolRun, qint64 serverRun) {
    const QString countSql = QStringLiteral("SELECT count(*) FROM sample_flag WHERE run_id = ?");
    if (scalar(spool, countSql, {spoolRun}) == scalar(server, countSql, {serverRun})) return 0;
    exec(server, QStringLiteral("DELETE FROM sample_flag WHERE run_id = ?"), {serverRun});
    return appendMissingRows(spool, server, QStringLiteral("sample_flag"),
                             QStringLiteral("channel, kind, from_t, to_t"), QStringLiteral("id"),
                             spoolRun, serverRun);
}

const QString kRunColumns = QStringLiteral(
    "name, ordinal, kind, feed_mm_min, range_from_mm, range_to_mm, description, extra_json, "
    "status");

/// One spool run onto the server, in one server transaction.
void uploadRun(QSqlDatabase& spool, QSqlDatabase& server, const QString& spoolId,
               const QSqlQuery& run, qint64 serverCampaign, UploadReport& report) {
    const qint64 spoolRun = run.value(0).toLongLong();
    if (!server.transaction()) throw server.lastError().text();
    // Two uploads of one spool at once (a run's uploader and a `sync`) take
    // turns, so that both cannot count the same rows missing and add them twice.
    if (backendOf(server) == StoreBackend::Postgres)
        exec(server, QStringLiteral("SELECT pg_advisory_xact_lock(hashtext(?))"), {spoolId});
    auto serverRun = scalar(server,
                            QStringLiteral("SELECT row_id FROM upload_origin WHERE spool_id = ? "
                                           "AND kind = 'run' AND spool_row_id = ?"),
                            {spoolId, spoolRun});
    if (serverRun == 0) {
        QVariantList values{serverCampaign};
        for (int k = 2; k <= 10; ++k) values << run.value(k);
        QSqlQuery insert =
            exec(server,
                 QStringLiteral("INSERT INTO run (campaign_id, %1) VALUES (?, ?, ?, ?, ?, ?, ?, "
                                "?, ?, ?)")
                     .arg(kRunColumns),
                 values);
        serverRun = insertedRowId(server, insert);
        recordOrigin(server, spoolId, QStringLiteral("run"), spoolRun, serverRun);
        ++report.runs;
    } else {
        exec(server, QStringLiteral("UPDATE run SET status = ? WHERE id = ?"),
             {run.value(10), serverRun});
    }
    report.blocks += upsertBlocks(spool, server, spoolRun, serverRun);
    report.rows +=
        appendMissingRows(spool, server, QStringLiteral("positioning"),
                          QStringLiteral("time_s, cycle, target_mm, direction, deviation_um"),
                          QStringLiteral("rowid"), spoolRun, serverRun);
    report.rows += appendMissingRows(spool, server, QStringLiteral("motion_segment"),
                                     QStringLiteral("start_s, end_s, from_mm, to_mm, feed_mm_min"),
                                     QStringLiteral("rowid"), spoolRun, serverRun);
    report.rows += appendMissingRows(spool, server, QStringLiteral("event_log"),
                                     QStringLiteral("logged_at, level, source, message"),
                                     QStringLiteral("id"), spoolRun, serverRun);
    // An event of a run belongs to the run's campaign, which has another id here.
    exec(server,
         QStringLiteral("UPDATE event_log SET campaign_id = ? WHERE run_id = ? AND campaign_id "
                        "IS NULL"),
         {serverCampaign, serverRun});
    report.rows += copyFlags(spool, server, spoolRun, serverRun);
    if (!server.commit()) throw server.lastError().text();
}

}  // namespace

QString spoolId(CampaignStore& spool) {
    QSqlQuery q(spool.database());
    return q.exec(QStringLiteral("SELECT spool_id FROM upload_spool")) && q.next()
               ? q.value(0).toString()
               : QString();
}

std::optional<QString> ensureSpoolId(CampaignStore& spool, QString* error) {
    if (QString id = spoolId(spool); !id.isEmpty()) return id;
    const QString id = QUuid::createUuid().toString(QUuid::WithoutBraces);
    QSqlQuery q(spool.database());
    if (!q.prepare(QStringLiteral("INSERT INTO upload_spool (spool_id) VALUES (?)"))) {
        *error = spool.path() + QStringLiteral(": ") + q.lastError().text();
        return std::nullopt;
    }
    q.addBindValue(id);
    if (!q.exec()) {
        *error = spool.path() + QStringLiteral(": cannot name the spool: ") + q.lastError().text();
        return std::nullopt;
    }
    return id;
}

std::optional<qint64> uploadedId(CampaignStore& server, const QString& spoolId, const QString& kind,
                                 qint64 spoolRowId) {
    try {
        const qint64 id = scalar(server.database(),
                                 QStringLiteral("SELECT row_id FROM upload_origin WHERE spool_id "
                                                "= ? AND kind = ? AND spool_row_id = ?"),
                                 {spoolId, kind, spoolRowId});
        return id ? std::optional(id) : std::nullopt;
    } catch (const QString&) {
        return std::nullopt;
    }
}

std::optional<UploadReport> uploadSpool(CampaignStore& spool, const QString& id,
                                        CampaignStore& server, QString* error) {
    UploadReport report;
    QSqlDatabase& from = spool.database();
    QSqlDatabase& to = server.database();
    try {
        std::vector<qint64> campaigns;
        for (QSqlQuery q = exec(from, QStringLiteral("SELECT id FROM campaign ORDER BY id"));
             q.next();)
            campaigns.push_back(q.value(0).toLongLong());
        for (qint64 campaign : campaigns) {
            if (uploadedId(server, id, QStringLiteral("campaign"), campaign)) continue;
            // The campaign's description (machine, screw, channels) without
            // its runs; the runs follow one by one below.
            QString why;
            auto description = spool.loadCampaign(campaign, &why);
            if (!description) throw why;
            description->runs.clear();
            if (!server.importCampaign(*description, &why, {}, [&](qint64 serverId) {
                    recordOrigin(to, id, QStringLiteral("campaign"), campaign, serverId);
                }))
                throw why;
            ++report.campaigns;
        }
        QSqlQuery runs = exec(
            from,
            QStringLiteral("SELECT id, campaign_id, %1 FROM run ORDER BY id").arg(kRunColumns));
        while (runs.next()) {
            ++report.runsInSpool;
            report.runsLogging += runs.value(10).toString() == QLatin1String("logging");
            const auto campaign =
                uploadedId(server, id, QStringLiteral("campaign"), runs.value(1).toLongLong());
            if (!campaign)
                throw QStringLiteral("campaign %1 is not on the server")
                    .arg(runs.value(1).toLongLong());
            try {
                uploadRun(from, to, id, runs, *campaign, report);
            } catch (const QString&) {
                to.rollback();
                throw;
            }
        }
    } catch (const QString& why) {
        *error = QStringLiteral("upload from %1 to %2 stopped: %3")
                     .arg(spool.path(), server.path(), why.simplified());
        return std::nullopt;
    }
    return report;
}

}  // namespace driftlab::db
