// Campaigns into the store, from memory (CampaignStore::importCampaign) or
// streamed from a bundle (importBundle), through one writer inside one transaction.
#include "db/CampaignImport.h"

#include <QSqlError>
#include <QSqlQuery>
#include <memory>

#include "core/bundle/BundleReader.h"
#include "db/SampleBlocks.h"
#include "db/SqlValues.h"
#include "db/SqliteStatement.h"
#include "db/StoreBackend.h"

namespace driftlab::db {
namespace {

/// Writes one campaign: metadata and runs first (begin), then sample rows as
/// they come, then motion and positioning (finish). Throws QString on failure;
/// the caller owns the transaction.
class CampaignWriter : public bundle::SampleRowSink {
public:
    explicit CampaignWriter(QSqlDatabase& db) : m_db(db) {}

    void begin(const Campaign& c) override {
        m_campaignId =
            insert(QStringLiteral(
                       "INSERT INTO campaign (name, nut_length_mm, travel_from_mm, travel_to_mm, "
                       "extra_json) VALUES (?, ?, ?, ?, ?)"),
                   {c.name, toSql(c.nut_length_mm),
                    toSql(c.travel_mm ? std::optional(c.travel_mm->from_mm) : std::nullopt),
                    toSql(c.travel_mm ? std::optional(c.travel_mm->to_mm) : std::nullopt),
                    jsonText(c.extra)},
                   true);
        insert(QStringLiteral("INSERT INTO machine VALUES (?, ?, ?, ?, ?)"),
               {m_campaignId, text(c.machine.name), text(c.machine.axis),
                text(c.machine.controller), jsonText(c.machine.extra)});
        if (const auto& s = c.screw)
            insert(QStringLiteral("INSERT INTO screw VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                   {m_campaignId, s->length_mm, s->diameter_mm, s->lead_mm, s->fixed_end_mm,
                    s->mounting, s->alpha_per_K, s->density_kg_m3, s->specific_heat_J_kgK,
                    s->conductivity_W_mK, jsonText(s->extra)});
        if (const auto& i = c.interferometer)
            insert(QStringLiteral("INSERT INTO interferometer VALUES (?, ?, ?, ?)"),
                   {m_campaignId, i->dead_path_mm, int(i->environment_compensation),
                    jsonText(i->extra)});

        // column_ordinal ties a channel to its column in the sample blocks.
        auto columnOrdinal = [&](const QString& name) -> QVariant {
            auto it = std::find(c.sample_columns.begin(), c.sample_columns.end(), name);
            return it == c.sample_columns.end() ? QVariant(QMetaType(QMetaType::Int))
                                                : QVariant(int(it - c.sample_columns.begin()));
        };
        const QString channelSql = QStringLiteral(
            "INSERT INTO channel (campaign_id, name, quantity, role, location, position_mm, "
            "declared_ordinal, column_ordinal, extra_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
        for (std::size_t k = 0; k < c.channels.size(); ++k) {
            const Channel& ch = c.channels[k];
            insert(channelSql, {m_campaignId, ch.id, toString(ch.quantity), toString(ch.role),
                                text(ch.location), toSql(ch.position_mm), int(k),
                                columnOrdinal(ch.id), jsonText(ch.extra)});
        }
        for (std::size_t k = 0; k < c.sample_columns.size(); ++k)
            if (isAxisColumn(c.sample_columns[k]))
                insert(channelSql,
                       {m_campaignId, c.sample_columns[k], QStringLiteral("axis"),
                        QVariant(QMetaType(QMetaType::QString)), QStringLiteral(""),
                        QVariant(QMetaType(QMetaType::Double)), QVariant(QMetaType(QMetaType::Int)),
                        int(k), QStringLiteral("{}")});

        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            const Run& run = c.runs[r];
            m_runIds.push_back(insert(
                QStringLiteral("INSERT INTO run (campaign_id, name, ordinal, kind, feed_mm_min, "
                               "range_from_mm, range_to_mm, description, extra_json) "
                               "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"),
                {m_campaignId, run.id, int(r), toString(run.kind), toSql(run.feed_mm_min),
                 toSql(run.range_mm ? std::optional(run.range_mm->from_mm) : std::nullopt),
                 toSql(run.range_mm ? std::optional(run.range_mm->to_mm) : std::nullopt),
                 text(run.description), jsonText(run.extra)},
                true));
        }
        m_samples = std::make_unique<SampleBlockWriter>(m_db, c.sample_columns.size(), m_runIds);
    }

    void row(std::size_t runIndex, double time_s, const double* values) override {
        m_samples->append(runIndex, time_s, values);
    }

    /// Writes what follows the samples; returns the campaign id.
    qint64 finish(const Campaign& c, const QByteArray& contentSha256) {
        m_samples->flush();
        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            const qint64 runId = m_runIds[r];
            for (const MotionSegment& m : c.runs[r].motion)
                insert(QStringLiteral("INSERT INTO motion_segment VALUES (?, ?, ?, ?, ?, ?)"),
                       {runId, m.start_s, m.end_s, m.from_mm, m.to_mm, m.feed_mm_min});
            for (const PositioningMeasurement& p : c.runs[r].positioning)
                insert(
                    QStringLiteral("INSERT INTO positioning VALUES (?, ?, ?, ?, ?, ?)"),
                    {runId, p.time_s, p.cycle, p.target_mm,
                     p.direction == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-"),
                     p.deviation_um});
        }
        if (!contentSha256.isEmpty())
            insert(QStringLiteral("UPDATE campaign SET content_sha256 = ? WHERE id = ?"),
                   {QString::fromLatin1(contentSha256), m_campaignId});
        return m_campaignId;
    }

private:
    /// Runs one INSERT; returns the new row's id when `returnsId`.
    qint64 insert(const QString& sql, const QVariantList& values, bool returnsId = false) {
        QSqlQuery q(m_db);
        if (!q.prepare(sql)) throw QStringLiteral("prepare failed: ") + q.lastError().text();
        for (const QVariant& v : values) q.addBindValue(v);
        if (!q.exec()) throw q.lastError().text();
        return returnsId ? insertedRowId(m_db, q) : 0;
    }

    QSqlDatabase& m_db;
    qint64 m_campaignId = 0;
    std::vector<qint64> m_runIds;
    std::unique_ptr<SampleBlockWriter> m_samples;
};

/// Rows are checked and dropped: the first pass of an import keeps nothing.
class DiscardingSink : public bundle::SampleRowSink {
public:
    void begin(const Campaign&) override {}
    void row(std::size_t, double, const double*) override {}
};

/// Why the import of campaign `name` into `store` failed, when SQLite's result
/// code says more than its text ("database or disk is full Unable to fetch
/// row"): in the user's words, with the store's path and the outcome. Empty for
/// other failures. Read before the rollback, which resets the result code.
QString storeFailure(CampaignStore& store, const QString& name) {
    sqlite3* handle = sqliteHandle(store.database());
    const QString condition = handle ? storeWriteCondition(sqlite3_errcode(handle)) : QString();
    if (condition.isEmpty()) return {};
    return QStringLiteral("%1: %2: nothing of '%3' was imported; the store is unchanged")
        .arg(store.path(), condition, name);
}

/// "path/file:line:column: why" of a reader's error.
QString located(const bundle::BundleSource& source, bundle::BundleError e) {
    e.file = source.displayPath(e.file);
    return e.toString();
}

}  // namespace

std::optional<qint64> CampaignStore::importCampaign(
    const Campaign& c, QString* error, const std::function<bool(double)>& progress,
    const std::function<void(qint64 campaignId)>& beforeCommit) {
    if (!m_db.transaction()) {
        const QString failure = storeFailure(*this, c.name);
        *error = failure.isEmpty()
                     ? QStringLiteral("cannot start a transaction: ") + m_db.lastError().text()
                     : failure;
        return std::nullopt;
    }
    try {
        CampaignWriter writer(m_db);
        writer.begin(c);
        std::size_t totalRows = 0, doneRows = 0;
        for (const Run& run : c.runs) totalRows += run.samples.rowCount();
        std::vector<double> row(c.sample_columns.size());
        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            const SampleSeries& s = c.runs[r].samples;
            for (std::size_t i = 0; i < s.rowCount(); ++i) {
                for (std::size_t k = 0; k < row.size(); ++k) row[k] = s.values[k][i];
                writer.row(r, s.time_s[i], row.data());
                if ((++doneRows & 0x3FFF) == 0 && progress &&
                    !progress(double(doneRows) / totalRows))
                    throw QStringLiteral("import cancelled");
            }
        }
        const qint64 id = writer.finish(c, {});
        if (beforeCommit) beforeCommit(id);
        if (!m_db.commit()) throw QStringLiteral("commit failed: ") + m_db.lastError().text();
        if (progress) progress(1.0);
        return id;
    } catch (const QString& why) {
        const QString failure = storeFailure(*this, c.name);
        m_db.rollback();
        *error =
            failure.isEmpty()
                ? QStringLiteral("import of '%1' into %2 rolled back: %3").arg(c.name, path(), why)
                : failure;
        return std::nullopt;
    }
}

BundleCheck checkBundle(const bundle::BundleSource& source,
                        const std::function<bool(double)>& progress) {
    BundleCheck check;
    DiscardingSink discard;
    const bundle::BundleReadResult read = bundle::readBundle(source, {progress, &discard});
    if (!read.ok()) {
        check.error = located(source, *read.error);
        return check;
    }
    check.name = read.campaign->name;
    check.warnings = read.warnings;
    QString error;
    check.contentSha256 = bundle::bundleContentSha256(source, &error);
    if (check.contentSha256.isEmpty())
        check.error = source.location() + QStringLiteral(": ") + error;
    return check;
}

std::optional<QString> alreadyImported(CampaignStore& store, const bundle::BundleSource& source,
                                       const BundleCheck& checked) {
    QSqlQuery q(store.database());
    q.prepare(
        QStringLiteral("SELECT id, name, imported_at FROM campaign WHERE content_sha256 = ? "
                       "ORDER BY id LIMIT 1"));
    q.addBindValue(QString::fromLatin1(checked.contentSha256));
    if (!q.exec() || !q.next()) return std::nullopt;
    return QStringLiteral(
               "%1 is already in %2 as campaign %3, '%4' (imported %5); --again "
               "imports it once more")
        .arg(source.location(), store.path(), q.value(0).toString(), q.value(1).toString(),
             q.value(2).toString());
}

BundleImportResult importBundle(CampaignStore& store, const bundle::BundleSource& source,
                                const BundleCheck& checked, const BundleImportOptions& options) {
    BundleImportResult result;
    QSqlDatabase& db = store.database();
    // On SQLite the write lock is taken first, waiting for another process's
    // as long as the busy timeout: Qt's deferred BEGIN would read (the check
    // for an earlier import) before it writes, and SQLite refuses such a
    // reader's later write at once, without waiting, when another holds the lock.
    QSqlQuery begin(db);
    const bool begun = backendOf(db) == StoreBackend::Sqlite
                           ? begin.exec(QStringLiteral("BEGIN IMMEDIATE"))
                           : db.transaction();
    if (!begun) {
        result.error = storeFailure(store, checked.name);
        if (result.error.isEmpty())
            result.error =
                store.path() + QStringLiteral(": cannot start a transaction: ") +
                (begin.lastError().isValid() ? begin.lastError() : db.lastError()).text();
        return result;
    }
    try {
        // Inside the transaction, so two imports of one bundle at once cannot both pass.
        if (!options.again)
            if (auto why = alreadyImported(store, source, checked)) throw *why;
        CampaignWriter writer(db);
        bundle::BundleReadResult read = bundle::readBundle(source, {options.progress, &writer});
        if (!read.ok()) throw located(source, *read.error);
        const qint64 id = writer.finish(*read.campaign, checked.contentSha256);
        if (!db.commit()) throw QStringLiteral("commit failed: ") + db.lastError().text();
        result.campaignId = id;
    } catch (const QString& why) {
        result.error = storeFailure(store, checked.name);
        if (result.error.isEmpty()) result.error = why;
        db.rollback();
    }
    return result;
}

}  // namespace driftlab::db
