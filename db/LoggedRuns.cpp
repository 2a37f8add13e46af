// The state of runs logged live: where an interrupted one stopped, and which
// 'logging' runs lost their logger (RunLogger.h).
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QSqlError>
#include <QSqlQuery>

#include "db/RunLogger.h"

namespace driftlab::db {

std::optional<LoggedRunState> loggedRunState(CampaignStore& store, qint64 runId, QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral(
        "SELECT r.campaign_id, r.name, r.status, "
        "(SELECT max(last_t) FROM sample_block WHERE run_id = r.id), "
        "(SELECT coalesce(sum(row_count), 0) FROM sample_block WHERE run_id = r.id), "
        "(SELECT max(time_s) FROM positioning WHERE run_id = r.id), "
        "(SELECT count(*) FROM positioning WHERE run_id = r.id), "
        "(SELECT count(*) FROM motion_segment WHERE run_id = r.id), "
        "(SELECT name FROM machine WHERE campaign_id = r.campaign_id), "
        "(SELECT extra_json FROM campaign WHERE id = r.campaign_id) FROM run r WHERE r.id = ?"));
    q.addBindValue(runId);
    if (!q.exec() || !q.next()) {
        if (error)
            *error = q.lastError().isValid()
                         ? q.lastError().text()
                         : QStringLiteral("%1: there is no run %2").arg(store.path()).arg(runId);
        return std::nullopt;
    }
    LoggedRunState s;
    s.run_id = runId;
    s.campaign_id = q.value(0).toLongLong();
    s.name = q.value(1).toString();
    s.status = q.value(2).toString();
    if (!q.value(3).isNull()) s.last_sample_s = q.value(3).toDouble();
    s.rows = q.value(4).toLongLong();
    if (!q.value(5).isNull()) s.last_reading_s = q.value(5).toDouble();
    s.readings = q.value(6).toLongLong();
    s.motion_segments = q.value(7).toLongLong();
    s.machine = q.value(8).toString();
    const QJsonObject extra = QJsonDocument::fromJson(q.value(9).toByteArray()).object();
    s.rig = extra.value(QStringLiteral("rig")).toString();
    if (extra.value(QStringLiteral("rig_real_time")).isBool())
        s.rig_real_time = extra.value(QStringLiteral("rig_real_time")).toBool();
    return s;
}

std::vector<QString> sampleColumns(CampaignStore& store, qint64 campaignId) {
    QSqlQuery q(store.database());
    q.prepare(
        QStringLiteral("SELECT name FROM channel WHERE campaign_id = ? AND column_ordinal "
                       "IS NOT NULL ORDER BY column_ordinal"));
    q.addBindValue(campaignId);
    std::vector<QString> columns;
    if (q.exec())
        while (q.next()) columns.push_back(q.value(0).toString());
    return columns;
}

std::vector<qint64> markInterruptedRuns(CampaignStore& store, QString* error) {
    std::vector<qint64> logging, interrupted;
    QSqlQuery q(store.database());
    if (!q.exec(QStringLiteral("SELECT id FROM run WHERE status = 'logging'"))) {
        if (error) *error = q.lastError().text();
        return {};
    }
    while (q.next()) logging.push_back(q.value(0).toLongLong());
    for (qint64 runId : logging) {
        // A lock we can take has no live owner: the logger crashed or was killed.
        QLockFile lock(RunLogger::lockPath(store.path(), runId));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) continue;
        const auto state = loggedRunState(store, runId, error);
        QSqlQuery mark(store.database());
        mark.prepare(QStringLiteral("UPDATE run SET status = 'interrupted' WHERE id = ?"));
        mark.addBindValue(runId);
        QSqlQuery event(store.database());
        event.prepare(
            QStringLiteral("INSERT INTO event_log (campaign_id, run_id, level, source, message) "
                           "SELECT campaign_id, id, 'warning', 'logger', ? FROM run WHERE id = ?"));
        event.addBindValue(QStringLiteral("the logger stopped without closing the run (crash, "
                                          "kill or power loss); data up to %1 s is kept")
                               .arg(state ? state->end_s() : 0));
        event.addBindValue(runId);
        if (!mark.exec() || !event.exec()) {
            if (error) *error = mark.lastError().text() + event.lastError().text();
            continue;
        }
        interrupted.push_back(runId);
    }
    return interrupted;
}

}  // namespace driftlab::db
