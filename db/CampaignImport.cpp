// CampaignStore::importCampaign: a whole campaign stored in one transaction.
#include <QSqlError>
#include <QSqlQuery>
#include <cmath>

#include "db/CampaignStore.h"
#include "db/SqlValues.h"
#include "db/SqliteStatement.h"

namespace driftlab::db {
namespace {

/// Runs prepared statements and turns the first failure into a thrown message,
/// so the import reads as a straight sequence inside one transaction.
class Inserter {
public:
    explicit Inserter(QSqlDatabase& db) : m_db(db) {}

    qint64 insert(const QString& sql, const QVariantList& values) {
        QSqlQuery q(m_db);
        if (!q.prepare(sql)) throw QStringLiteral("prepare failed: ") + q.lastError().text();
        for (const QVariant& v : values) q.addBindValue(v);
        if (!q.exec()) throw q.lastError().text();
        return q.lastInsertId().toLongLong();
    }

private:
    QSqlDatabase& m_db;
};

}  // namespace

std::optional<qint64> CampaignStore::importCampaign(const Campaign& c, QString* error,
                                                    const std::function<bool(double)>& progress) {
    if (!m_db.transaction()) {
        *error = QStringLiteral("cannot start a transaction: ") + m_db.lastError().text();
        return std::nullopt;
    }
    try {
        Inserter sql(m_db);
        const qint64 campaignId = sql.insert(
            QStringLiteral(
                "INSERT INTO campaign (name, nut_length_mm, travel_from_mm, travel_to_mm, "
                "extra_json) VALUES (?, ?, ?, ?, ?)"),
            {c.name, toSql(c.nut_length_mm),
             toSql(c.travel_mm ? std::optional(c.travel_mm->from_mm) : std::nullopt),
             toSql(c.travel_mm ? std::optional(c.travel_mm->to_mm) : std::nullopt),
             jsonText(c.extra)});
        sql.insert(QStringLiteral("INSERT INTO machine VALUES (?, ?, ?, ?, ?)"),
                   {campaignId, text(c.machine.name), text(c.machine.axis),
                    text(c.machine.controller), jsonText(c.machine.extra)});
        if (const auto& s = c.screw)
            sql.insert(QStringLiteral("INSERT INTO screw VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                       {campaignId, s->length_mm, s->diameter_mm, s->lead_mm, s->fixed_end_mm,
                        s->mounting, s->alpha_per_K, s->density_kg_m3, s->specific_heat_J_kgK,
                        s->conductivity_W_mK, jsonText(s->extra)});
        if (const auto& i = c.interferometer)
            sql.insert(QStringLiteral("INSERT INTO interferometer VALUES (?, ?, ?, ?)"),
                       {campaignId, i->dead_path_mm, int(i->environment_compensation),
                        jsonText(i->extra)});

        // Channel row id of every samples.csv column, in column order.
        auto columnOrdinal = [&](const QString& name) -> QVariant {
            auto it = std::find(c.sample_columns.begin(), c.sample_columns.end(), name);
            return it == c.sample_columns.end() ? QVariant(QMetaType(QMetaType::Int))
                                                : QVariant(int(it - c.sample_columns.begin()));
        };
        std::vector<qint64> columnChannel(c.sample_columns.size());
        const QString channelSql = QStringLiteral(
            "INSERT INTO channel (campaign_id, name, quantity, role, location, position_mm, "
            "declared_ordinal, column_ordinal, extra_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
        for (std::size_t k = 0; k < c.channels.size(); ++k) {
            const Channel& ch = c.channels[k];
            QVariant ordinal = columnOrdinal(ch.id);
            qint64 id =
                sql.insert(channelSql, {campaignId, ch.id, toString(ch.quantity), toString(ch.role),
                                        text(ch.location), toSql(ch.position_mm), int(k), ordinal,
                                        jsonText(ch.extra)});
            if (!ordinal.isNull()) columnChannel[std::size_t(ordinal.toInt())] = id;
        }
        for (std::size_t k = 0; k < c.sample_columns.size(); ++k)
            if (isAxisColumn(c.sample_columns[k]))
                columnChannel[k] =
                    sql.insert(channelSql,
                               {campaignId, c.sample_columns[k], QStringLiteral("axis"),
                                QVariant(QMetaType(QMetaType::QString)), QStringLiteral(""),
                                QVariant(QMetaType(QMetaType::Double)),
                                QVariant(QMetaType(QMetaType::Int)), int(k), QStringLiteral("{}")});

        SqliteStatement sampleInsert(
            sqliteHandle(m_db),
            "INSERT INTO sample (run_id, t, channel_id, value) VALUES (?, ?, ?, ?)");
        if (!sampleInsert.ok()) throw sampleInsert.error();
        std::size_t totalRows = 0, doneRows = 0;
        for (const Run& run : c.runs) totalRows += run.samples.rowCount();

        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            const Run& run = c.runs[r];
            const qint64 runId = sql.insert(
                QStringLiteral("INSERT INTO run (campaign_id, name, ordinal, kind, feed_mm_min, "
                               "range_from_mm, range_to_mm, description, extra_json) "
                               "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                {campaignId, run.id, int(r), toString(run.kind), toSql(run.feed_mm_min),
                 toSql(run.range_mm ? std::optional(run.range_mm->from_mm) : std::nullopt),
                 toSql(run.range_mm ? std::optional(run.range_mm->to_mm) : std::nullopt),
                 text(run.description), jsonText(run.extra)});
            for (const MotionSegment& m : run.motion)
                sql.insert(QStringLiteral("INSERT INTO motion_segment VALUES (?, ?, ?, ?, ?, ?)"),
                           {runId, m.start_s, m.end_s, m.from_mm, m.to_mm, m.feed_mm_min});
            for (const PositioningMeasurement& p : run.positioning)
                sql.insert(
                    QStringLiteral("INSERT INTO positioning VALUES (?, ?, ?, ?, ?, ?)"),
                    {runId, p.time_s, p.cycle, p.target_mm,
                     p.direction == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-"),
                     p.deviation_um});

            const SampleSeries& s = run.samples;
            sampleInsert.bind(1, runId);
            for (std::size_t row = 0; row < s.rowCount(); ++row) {
                sampleInsert.bind(2, s.time_s[row]);
                for (std::size_t k = 0; k < s.values.size(); ++k) {
                    const double v = s.values[k][row];
                    if (std::isnan(v)) continue;  // a missing sample has no row
                    sampleInsert.bind(3, columnChannel[k]);
                    sampleInsert.bind(4, v);
                    if (!sampleInsert.execute()) throw sampleInsert.error();
                }
                if ((++doneRows & 0x3FFF) == 0 && progress &&
                    !progress(double(doneRows) / totalRows))
                    throw QStringLiteral("import cancelled");
            }
        }
        if (!m_db.commit()) throw QStringLiteral("commit failed: ") + m_db.lastError().text();
        if (progress) progress(1.0);
        return campaignId;
    } catch (const QString& why) {
        m_db.rollback();
        *error = QStringLiteral("import of '%1' into %2 rolled back: %3").arg(c.name, path(), why);
        return std::nullopt;
    }
}

}  // namespace driftlab::db
