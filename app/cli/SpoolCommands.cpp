// sync, and the spool that `run --db postgresql://…` logs into.
#include "app/cli/SpoolCommands.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include "app/cli/CliCommon.h"
#include "db/CampaignStore.h"
#include "db/RunLogger.h"
#include "db/SpoolUpload.h"
#include "db/StoreBackend.h"

namespace driftlab::cli {

QCommandLineOption spoolOption() {
    return {QStringLiteral("spool"),
            QStringLiteral("With a postgresql:// --db: the local SQLite store runs are logged "
                           "into first and uploaded from (default: "
                           "~/.local/share/driftlab/spool.sqlite)."),
            QStringLiteral("FILE")};
}

QString spoolPath(const QCommandLineParser& parser, const QCommandLineOption& spool) {
    if (parser.isSet(spool)) return parser.value(spool);
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
                           QStringLiteral("/driftlab");
    if (!QDir().mkpath(folder))
        throw CliError(
            QStringLiteral("%1: cannot create the spool's folder (give --spool FILE)").arg(folder));
    return folder + QStringLiteral("/spool.sqlite");
}

QString prepareSpool(const QString& path) {
    QString error;
    if (!QFileInfo::exists(path)) {
        auto created = db::CampaignStore::open(path, db::StoreAccess::CreateIfMissing, &error);
        if (!created || !created->publish(&error)) throw CliError(error);
    }
    auto spool = db::CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    if (!spool) throw CliError(error);
    const auto id = db::ensureSpoolId(*spool, &error);
    if (!id) throw CliError(error);
    return *id;
}

int syncCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption spool = spoolOption();
    const QCommandLineOption db{
        QStringLiteral("db"), QStringLiteral("The server store: postgresql://USER@HOST[:PORT]/DB."),
        QStringLiteral("URL")};
    parseArguments(parser, args, {spool, db}, {{}, {}, {}, {db}});
    const QString url = parser.value(db);
    if (!db::isServerStoreUrl(url))
        throw CliError(QStringLiteral("--db: '%1' is not a postgresql:// URL; sync uploads a "
                                      "spool to a server store")
                           .arg(url),
                       2);
    const QString path = spoolPath(parser, spool);
    if (!QFileInfo::exists(path)) throw CliError(QStringLiteral("%1: no such spool").arg(path));
    const QString id = prepareSpool(path);
    QString error;
    {
        // Runs whose logger died (crash, kill, power loss) go up as interrupted.
        auto writable = db::CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
        if (!writable) throw CliError(error);
        db::markInterruptedRuns(*writable, &error);
    }
    auto source = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    if (!source) throw CliError(error);
    auto server = db::CampaignStore::open(url, db::StoreAccess::ReadWrite, &error);
    if (!server) throw CliError(error);
    const auto report = db::uploadSpool(*source, id, *server, &error);
    if (!report) throw CliError(error);
    if (parser.isSet(QStringLiteral("json")))
        printJson({{QStringLiteral("spool"), path},
                   {QStringLiteral("server"), server->path()},
                   {QStringLiteral("new_campaigns"), report->campaigns},
                   {QStringLiteral("new_runs"), report->runs},
                   {QStringLiteral("blocks_written"), report->blocks},
                   {QStringLiteral("rows_added"), report->rows},
                   {QStringLiteral("runs_in_spool"), report->runsInSpool},
                   {QStringLiteral("runs_logging"), report->runsLogging}});
    else
        printLine(QStringLiteral("%1 → %2: %3 new campaigns, %4 new runs, %5 sample blocks "
                                 "written, %6 rows added; the spool's %7 runs are on the server")
                      .arg(path, server->path())
                      .arg(report->campaigns)
                      .arg(report->runs)
                      .arg(report->blocks)
                      .arg(report->rows)
                      .arg(report->runsInSpool));
    return 0;
}

}  // namespace driftlab::cli
