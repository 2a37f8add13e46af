// bench: the live logger's sustained rate (docs/benchmarks.md): rows of a
// 16-column campaign appended through db::RunLogger, which commits at least
// every second with a synchronous commit in WAL mode, against a bare sqlite3
// bulk insert of the same rows (one prepared INSERT per row, one
// transaction, no durability between commits) into a plain table in the
// same folder, in the same process. Figures in samples (values) per second.
// Given a server store, also the rate at which the logged run goes up to it
// (db/SpoolUpload.h): a rig logging into a server logs into its spool at the
// first rate and is uploaded at this one (docs/lab-store.md).
#include <sqlite3.h>

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "bench/BenchFigures.h"
#include "core/rig/CampaignSimulator.h"
#include "db/RunLogger.h"
#include "db/SpoolUpload.h"

namespace driftlab::bench {
namespace {

/// Rows that look like a rig's: slow temperatures, a moving axis, some NaN.
std::vector<double> benchRows(std::size_t rows, std::size_t columns) {
    std::vector<double> v(rows * columns);
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < columns; ++c)
            v[r * columns + c] =
                (r + c) % 97 == 0 ? std::nan("") : 20.0 + 0.01 * c + 1e-4 * double(r % 5000);
    return v;
}

double loggerSeconds(const QString& path, const std::vector<double>& rows, std::size_t columns) {
    QString error;
    auto created = db::CampaignStore::open(path, db::StoreAccess::CreateIfMissing, &error);
    if (!created || !created->publish(&error))
        throw CliError(QStringLiteral("logging bench: ") + error);
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    Campaign header = rig::rigCampaignHeader(rig::RigSpec{}, true);
    const auto campaignId = store ? store->importCampaign(header, &error) : std::nullopt;
    if (!campaignId || header.sample_columns.size() != columns)
        throw CliError(QStringLiteral("logging bench: ") + error);
    QElapsedTimer timer;
    timer.start();
    db::RunHeader run;
    run.name = QStringLiteral("B1");
    auto logger = db::RunLogger::begin(*store, *campaignId, run, &error);
    if (!logger) throw CliError(QStringLiteral("logging bench: ") + error);
    const std::size_t count = rows.size() / columns;
    for (std::size_t r = 0; r < count; ++r) {
        logger->appendRow(double(r) * 0.01, rows.data() + r * columns);
        if (r % 1024 == 0 && !logger->commitIfDue(&error))
            throw CliError(QStringLiteral("logging bench: ") + error);
    }
    if (!logger->finish(QStringLiteral("complete"), &error))
        throw CliError(QStringLiteral("logging bench: ") + error);
    return timer.nsecsElapsed() * 1e-9;
}

double bareSqliteSeconds(const QString& path, const std::vector<double>& rows,
                         std::size_t columns) {
    sqlite3* handle = nullptr;
    if (sqlite3_open(path.toUtf8().constData(), &handle) != SQLITE_OK)
        throw CliError(QStringLiteral("logging bench: cannot open ") + path);
    QString create = QStringLiteral("CREATE TABLE bare (t REAL");
    QString insert = QStringLiteral("INSERT INTO bare VALUES (?");
    for (std::size_t c = 0; c < columns; ++c) {
        create += QStringLiteral(", c%1 REAL").arg(c);
        insert += QStringLiteral(", ?");
    }
    sqlite3_exec(handle, "PRAGMA journal_mode = WAL", nullptr, nullptr, nullptr);
    sqlite3_exec(handle, (create + QStringLiteral(")")).toUtf8().constData(), nullptr, nullptr,
                 nullptr);
    QElapsedTimer timer;
    timer.start();
    sqlite3_stmt* statement = nullptr;
    sqlite3_prepare_v2(handle, (insert + QStringLiteral(")")).toUtf8().constData(), -1, &statement,
                       nullptr);
    sqlite3_exec(handle, "BEGIN", nullptr, nullptr, nullptr);
    const std::size_t count = rows.size() / columns;
    for (std::size_t r = 0; r < count; ++r) {
        sqlite3_bind_double(statement, 1, double(r) * 0.01);
        for (std::size_t c = 0; c < columns; ++c) {
            const double v = rows[r * columns + c];
            if (std::isnan(v))
                sqlite3_bind_null(statement, int(c) + 2);
            else
                sqlite3_bind_double(statement, int(c) + 2, v);
        }
        sqlite3_step(statement);
        sqlite3_reset(statement);
    }
    const bool ok = sqlite3_exec(handle, "COMMIT", nullptr, nullptr, nullptr) == SQLITE_OK;
    sqlite3_finalize(statement);
    sqlite3_close(handle);
    if (!ok) throw CliError(QStringLiteral("logging bench: the bare insert failed"));
    return timer.nsecsElapsed() * 1e-9;
}

/// Seconds to upload the spool at `path` (one logged run) to the server store.
double uploadSeconds(const QString& path, const QString& serverUrl) {
    QString error;
    std::optional<QString> id;
    if (auto spool = db::CampaignStore::open(path, db::StoreAccess::ReadWrite, &error))
        id = db::ensureSpoolId(*spool, &error);
    auto spool = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    auto server = db::CampaignStore::open(serverUrl, db::StoreAccess::ReadWrite, &error);
    if (!id || !spool || !server) throw CliError(QStringLiteral("logging bench: ") + error);
    QElapsedTimer timer;
    timer.start();
    if (!db::uploadSpool(*spool, *id, *server, &error))
        throw CliError(QStringLiteral("logging bench: ") + error);
    return timer.nsecsElapsed() * 1e-9;
}

}  // namespace

QJsonObject loggingFigures(int repetitions, const QString& serverUrl) {
    const std::size_t columns = rig::rigCampaignHeader(rig::RigSpec{}, true).sample_columns.size();
    const std::size_t rowCount = 1'000'000;
    const std::vector<double> rows = benchRows(rowCount, columns);
    std::vector<double> logged, bare, uploaded;
    for (int i = 0; i < repetitions; ++i) {
        QTemporaryDir dir;
        logged.push_back(loggerSeconds(dir.filePath(QStringLiteral("log.sqlite")), rows, columns));
        if (!serverUrl.isEmpty())
            uploaded.push_back(
                uploadSeconds(dir.filePath(QStringLiteral("log.sqlite")), serverUrl));
        bare.push_back(
            bareSqliteSeconds(dir.filePath(QStringLiteral("bare.sqlite")), rows, columns));
        printProgress(QStringLiteral("logging"), (i + 1.0) / repetitions);
    }
    const double samples = double(rowCount * columns);
    const double ours = samples / median(logged);
    const double theirs = samples / median(bare);
    QJsonObject figures{{QStringLiteral("logging_samples_per_s"), ours},
                        {QStringLiteral("logging_bare_sqlite_samples_per_s"), theirs},
                        {QStringLiteral("logging_ratio_to_bare_sqlite"), ours / theirs}};
    if (!uploaded.empty())
        figures[QStringLiteral("logging_postgres_samples_per_s")] = samples / median(uploaded);
    return figures;
}

void printLoggingLine(const QJsonObject& f) {
    printLine(
        QStringLiteral("live logging    %1 million samples/s, a synchronous commit every "
                       "second (bare sqlite3 bulk insert: %2 million; %3 % of it)")
            .arg(f[QStringLiteral("logging_samples_per_s")].toDouble() * 1e-6, 0, 'f', 2)
            .arg(f[QStringLiteral("logging_bare_sqlite_samples_per_s")].toDouble() * 1e-6, 0, 'f',
                 2)
            .arg(100 * f[QStringLiteral("logging_ratio_to_bare_sqlite")].toDouble(), 0, 'f', 0));
    if (f.contains(QStringLiteral("logging_postgres_samples_per_s")))
        printLine(QStringLiteral("  to PostgreSQL %1 million samples/s uploaded from the spool to "
                                 "the server store")
                      .arg(f[QStringLiteral("logging_postgres_samples_per_s")].toDouble() * 1e-6, 0,
                           'f', 2));
}

}  // namespace driftlab::bench
