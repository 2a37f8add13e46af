#include "db/SampleFlagStore.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QSqlRecord>
#include <algorithm>
#include <set>
#include <stdexcept>
#include <tuple>

namespace driftlab::db {
namespace {

bool fail(QString* error, const CampaignStore& store, const QString& why) {
    if (error) *error = QStringLiteral("%1: %2").arg(store.path(), why);
    return false;
}

using RangeKey = std::tuple<QString, QString, double, double>;

RangeKey keyOf(const QString& channel, const QString& kind, double from_s, double to_s) {
    return {channel, kind, from_s, to_s};
}

/// Schema v7 added the keep choice; an older store read without migrating has none.
bool hasKeptColumn(CampaignStore& store) {
    return store.database().record(QStringLiteral("sample_flag")).contains(QStringLiteral("kept"));
}

}  // namespace

bool replaceRunFlags(CampaignStore& store, qint64 runDbId,
                     const std::vector<sensors::FlaggedRange>& ranges, QString* error) {
    if (store.access() == StoreAccess::ReadOnly)
        return fail(error, store, QStringLiteral("opened read-only: cannot store sensor flags"));
    QSqlDatabase& db = store.database();
    if (!db.transaction())
        return fail(error, store,
                    QStringLiteral("cannot store sensor flags: %1").arg(db.lastError().text()));
    QSqlQuery q(db);
    const auto rollback = [&](const QString& why) {
        db.rollback();
        return fail(error, store,
                    QStringLiteral("run %1: cannot store sensor flags: %2").arg(runDbId).arg(why));
    };
    q.prepare(QStringLiteral("SELECT count(*) FROM run WHERE id = ?"));
    q.addBindValue(runDbId);
    if (!q.exec() || !q.next()) return rollback(q.lastError().text());
    if (q.value(0).toInt() != 1) return rollback(QStringLiteral("no such run"));
    // The stretches the user kept: kept again when the check finds them again.
    std::set<RangeKey> kept;
    q.prepare(QStringLiteral(
        "SELECT channel, kind, from_t, to_t FROM sample_flag WHERE run_id = ? AND kept = 1"));
    q.addBindValue(runDbId);
    if (!q.exec()) return rollback(q.lastError().text());
    while (q.next())
        kept.insert(keyOf(q.value(0).toString(), q.value(1).toString(), q.value(2).toDouble(),
                          q.value(3).toDouble()));
    q.prepare(QStringLiteral("DELETE FROM sample_flag WHERE run_id = ?"));
    q.addBindValue(runDbId);
    if (!q.exec()) return rollback(q.lastError().text());
    q.prepare(
        QStringLiteral("INSERT INTO sample_flag (run_id, channel, kind, from_t, to_t, kept) "
                       "VALUES (?, ?, ?, ?, ?, ?)"));
    for (const sensors::FlaggedRange& r : ranges) {
        const QString kind = sensors::toString(r.fault);
        q.bindValue(0, runDbId);
        q.bindValue(1, r.channel);
        q.bindValue(2, kind);
        q.bindValue(3, r.from_s);
        q.bindValue(4, r.to_s);
        q.bindValue(5, int(kept.count(keyOf(r.channel, kind, r.from_s, r.to_s))));
        if (!q.exec())
            return rollback(QStringLiteral("%1 %2 %3–%4 s: %5")
                                .arg(r.channel, sensors::toString(r.fault))
                                .arg(r.from_s)
                                .arg(r.to_s)
                                .arg(q.lastError().text()));
    }
    if (!db.commit()) return rollback(db.lastError().text());
    return true;
}

std::optional<std::vector<sensors::FlaggedRange>> flagRun(
    CampaignStore& store, qint64 runDbId, const sensors::SensorHealthSettings& settings,
    QString* error, const std::vector<sensors::RedundantPair>& redundant) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral("SELECT campaign_id, name FROM run WHERE id = ?"));
    q.addBindValue(runDbId);
    if (!q.exec() || !q.next()) {
        fail(error, store, QStringLiteral("no run with id %1").arg(runDbId));
        return std::nullopt;
    }
    const qint64 campaignId = q.value(0).toLongLong();
    const QString name = q.value(1).toString();
    // The campaign's channels (quantity, role) decide which checks apply.
    const std::optional<Campaign> campaign = store.loadCampaign(campaignId, error);
    if (!campaign) return std::nullopt;
    const auto run = std::find_if(campaign->runs.begin(), campaign->runs.end(),
                                  [&](const Run& r) { return r.id == name; });
    if (run == campaign->runs.end()) {
        fail(error, store,
             QStringLiteral("run %1 is not in campaign %2").arg(name).arg(campaignId));
        return std::nullopt;
    }
    std::vector<sensors::FlaggedRange> ranges;
    try {
        ranges = sensors::flaggedRanges(
            sensors::checkRun(run->samples, campaign->channels, redundant, settings));
    } catch (const std::invalid_argument& e) {
        fail(error, store,
             QStringLiteral("run %1: %2").arg(name, QString::fromStdString(e.what())));
        return std::nullopt;
    }
    if (!replaceRunFlags(store, runDbId, ranges, error)) return std::nullopt;
    return ranges;
}

std::optional<qint64> runDbId(CampaignStore& store, qint64 campaignId, const QString& runName,
                              QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral("SELECT id FROM run WHERE campaign_id = ? AND name = ?"));
    q.addBindValue(campaignId);
    q.addBindValue(runName);
    if (!q.exec() || !q.next()) {
        fail(error, store,
             QStringLiteral("campaign %1 has no run '%2'").arg(campaignId).arg(runName));
        return std::nullopt;
    }
    return q.value(0).toLongLong();
}

std::optional<std::map<QString, std::vector<sensors::FlaggedRange>>> loadSampleFlags(
    CampaignStore& store, qint64 campaignId, QString* error) {
    const auto stored = loadStoredFlags(store, campaignId, error);
    if (!stored) return std::nullopt;
    std::map<QString, std::vector<sensors::FlaggedRange>> flags;
    for (const auto& [run, list] : *stored)
        for (const StoredFlag& flag : list) flags[run].push_back(flag.range);
    return flags;
}

std::optional<std::map<QString, std::vector<StoredFlag>>> loadStoredFlags(CampaignStore& store,
                                                                          qint64 campaignId,
                                                                          QString* error) {
    std::map<QString, std::vector<StoredFlag>> flags;
    QSqlQuery q(store.database());
    // A store below v5 opened read-only has no table and so no flags. (Asked
    // through Qt SQL, which knows how each back end lists its tables.)
    if (!store.database().tables().contains(QStringLiteral("sample_flag"))) return flags;
    q.prepare(QStringLiteral("SELECT r.name, f.channel, f.kind, f.from_t, f.to_t, f.id, %1 "
                             "FROM sample_flag f JOIN run r ON r.id = f.run_id "
                             "WHERE r.campaign_id = ? ORDER BY r.ordinal, f.id")
                  .arg(hasKeptColumn(store) ? QStringLiteral("f.kept") : QStringLiteral("0")));
    q.addBindValue(campaignId);
    if (!q.exec()) {
        fail(error, store,
             QStringLiteral("cannot read sensor flags: %1").arg(q.lastError().text()));
        return std::nullopt;
    }
    while (q.next()) {
        const auto fault = sensors::sensorFaultFromString(q.value(2).toString());
        if (!fault) {
            fail(error, store,
                 QStringLiteral("sensor flag of run %1, %2: unknown kind '%3'")
                     .arg(q.value(0).toString(), q.value(1).toString(), q.value(2).toString()));
            return std::nullopt;
        }
        flags[q.value(0).toString()].push_back(
            {q.value(5).toLongLong(),
             {q.value(1).toString(), *fault, q.value(3).toDouble(), q.value(4).toDouble()},
             q.value(6).toInt() != 0});
    }
    return flags;
}

bool setFlagsKept(CampaignStore& store, const std::vector<qint64>& flagIds, bool kept,
                  QString* error) {
    if (store.access() == StoreAccess::ReadOnly)
        return fail(error, store, QStringLiteral("opened read-only: cannot keep or mask flags"));
    QSqlDatabase& db = store.database();
    if (!db.transaction())
        return fail(error, store,
                    QStringLiteral("cannot keep or mask flags: %1").arg(db.lastError().text()));
    QSqlQuery q(db);
    q.prepare(QStringLiteral("UPDATE sample_flag SET kept = ? WHERE id = ?"));
    for (const qint64 id : flagIds) {
        q.bindValue(0, int(kept));
        q.bindValue(1, id);
        if (!q.exec() || q.numRowsAffected() != 1) {
            const QString why = q.lastError().text();
            db.rollback();
            return fail(error, store,
                        QStringLiteral("sensor flag %1: %2")
                            .arg(id)
                            .arg(why.trimmed().isEmpty() ? QStringLiteral("no such flag") : why));
        }
    }
    if (!db.commit()) {
        const QString why = db.lastError().text();
        db.rollback();
        return fail(error, store, QStringLiteral("cannot keep or mask flags: %1").arg(why));
    }
    return true;
}

}  // namespace driftlab::db
