// CampaignStore::loadCampaign: reads a campaign back in the shape it was imported.
#include <QSqlError>
#include <QSqlQuery>
#include <limits>

#include "db/CampaignStore.h"
#include "db/SampleBlocks.h"
#include "db/SqlValues.h"
#include "db/StoreBackend.h"

namespace driftlab::db {
namespace {

QSqlQuery select(const QSqlDatabase& db, const QString& sql, qint64 id) {
    QSqlQuery q(db);
    // Forward-only is SQLite's cheap path; Qt's PostgreSQL driver then streams
    // rows one by one and loses them when the next query (the nested reads of
    // a run) starts, so there the whole (small) result is fetched at once.
    q.setForwardOnly(backendOf(db) == StoreBackend::Sqlite);
    if (!q.prepare(sql)) throw q.lastError().text();
    q.addBindValue(id);
    if (!q.exec()) throw q.lastError().text();
    return q;
}

std::optional<RangeMm> rangeOf(const QVariant& from, const QVariant& to) {
    if (from.isNull() || to.isNull()) return std::nullopt;
    return RangeMm{from.toDouble(), to.toDouble()};
}

}  // namespace

std::optional<Campaign> CampaignStore::loadCampaign(qint64 id, QString* error) const {
    try {
        Campaign c;
        QSqlQuery q = select(
            m_db,
            QStringLiteral("SELECT name, nut_length_mm, travel_from_mm, travel_to_mm, extra_json "
                           "FROM campaign WHERE id = ?"),
            id);
        if (!q.next()) throw QStringLiteral("no campaign with id %1").arg(id);
        c.name = q.value(0).toString();
        c.nut_length_mm = optionalDouble(q.value(1));
        c.travel_mm = rangeOf(q.value(2), q.value(3));
        c.extra = jsonObject(q.value(4));

        q = select(
            m_db,
            QStringLiteral(
                "SELECT name, axis, controller, extra_json FROM machine WHERE campaign_id = ?"),
            id);
        if (q.next())
            c.machine = {q.value(0).toString(), q.value(1).toString(), q.value(2).toString(),
                         jsonObject(q.value(3))};

        q = select(
            m_db,
            QStringLiteral(
                "SELECT length_mm, diameter_mm, lead_mm, fixed_end_mm, mounting, alpha_per_K, "
                "density_kg_m3, specific_heat_J_kgK, conductivity_W_mK, extra_json "
                "FROM screw WHERE campaign_id = ?"),
            id);
        if (q.next())
            c.screw = Screw{q.value(0).toDouble(), q.value(1).toDouble(), q.value(2).toDouble(),
                            q.value(3).toDouble(), q.value(4).toString(), q.value(5).toDouble(),
                            q.value(6).toDouble(), q.value(7).toDouble(), q.value(8).toDouble(),
                            jsonObject(q.value(9))};

        q = select(m_db,
                   QStringLiteral("SELECT dead_path_mm, environment_compensation, extra_json "
                                  "FROM interferometer WHERE campaign_id = ?"),
                   id);
        if (q.next())
            c.interferometer =
                Interferometer{q.value(0).toDouble(), q.value(1).toBool(), jsonObject(q.value(2))};

        q = select(m_db,
                   QStringLiteral(
                       "SELECT id, name, quantity, role, location, position_mm, declared_ordinal, "
                       "column_ordinal, extra_json FROM channel WHERE campaign_id = ? "
                       "ORDER BY declared_ordinal, column_ordinal"),
                   id);
        std::vector<std::pair<int, QString>> columns;
        while (q.next()) {
            if (!q.value(7).isNull())
                columns.emplace_back(q.value(7).toInt(), q.value(1).toString());
            if (q.value(6).isNull()) continue;  // an axis column, not a declared channel
            Channel ch;
            ch.id = q.value(1).toString();
            ch.quantity = quantityFromString(q.value(2).toString()).value_or(Quantity::Temperature);
            ch.role = roleFromString(q.value(3).toString()).value_or(ChannelRole::Other);
            ch.location = q.value(4).toString();
            ch.position_mm = optionalDouble(q.value(5));
            ch.extra = jsonObject(q.value(8));
            c.channels.push_back(std::move(ch));
        }
        std::sort(columns.begin(), columns.end());
        for (const auto& [ordinal, name] : columns) c.sample_columns.push_back(name);

        q = select(
            m_db,
            QStringLiteral(
                "SELECT id, name, kind, feed_mm_min, range_from_mm, range_to_mm, description, "
                "extra_json FROM run WHERE campaign_id = ? ORDER BY ordinal"),
            id);
        while (q.next()) {
            Run run;
            const qint64 runId = q.value(0).toLongLong();
            run.id = q.value(1).toString();
            run.kind = runKindFromString(q.value(2).toString()).value_or(RunKind::Moving);
            run.feed_mm_min = optionalDouble(q.value(3));
            run.range_mm = rangeOf(q.value(4), q.value(5));
            run.description = q.value(6).toString();
            run.extra = jsonObject(q.value(7));

            QSqlQuery m =
                select(m_db,
                       QStringLiteral("SELECT start_s, end_s, from_mm, to_mm, feed_mm_min FROM "
                                      "motion_segment WHERE run_id = ? ORDER BY rowid"),
                       runId);
            while (m.next())
                run.motion.push_back({m.value(0).toDouble(), m.value(1).toDouble(),
                                      m.value(2).toDouble(), m.value(3).toDouble(),
                                      m.value(4).toDouble()});
            QSqlQuery p = select(
                m_db,
                QStringLiteral("SELECT time_s, cycle, target_mm, direction, deviation_um FROM "
                               "positioning WHERE run_id = ? ORDER BY rowid"),
                runId);
            while (p.next())
                run.positioning.push_back(
                    {p.value(0).toDouble(), p.value(1).toInt(), p.value(2).toDouble(),
                     p.value(3).toString() == QLatin1String("+") ? Direction::Positive
                                                                 : Direction::Negative,
                     p.value(4).toDouble()});

            run.samples.columns = c.sample_columns;
            loadSampleBlocks(m_db, runId, run.samples);
            c.runs.push_back(std::move(run));
        }
        return c;
    } catch (const QString& why) {
        *error = QStringLiteral("%1: campaign %2: %3").arg(path()).arg(id).arg(why);
        return std::nullopt;
    }
}

}  // namespace driftlab::db
