// sync, and the spool that `run --db postgresql://…` logs into.
#include "app/cli/SpoolCommands.h"

#include <QFileInfo>

#include "app/cli/CliCommon.h"
#include "db/CampaignStore.h"
#include "db/SpoolFile.h"
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
    QString error;
    const QString path = db::defaultSpoolPath(&error);
    if (path.isEmpty()) throw CliError(error + QStringLiteral(" (give --spool FILE)"));
    return path;
}

QString prepareSpool(const QString& path) {
    QString error;
    const auto id = db::prepareSpool(path, &error);
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
    // Said before the server is asked: a mistyped spool is the likelier fault.
    if (!QFileInfo::exists(path)) throw CliError(QStringLiteral("%1: no such spool").arg(path));
    QString error;
    auto server = db::CampaignStore::open(url, db::StoreAccess::ReadWrite, &error);
    if (!server) throw CliError(error);
    const auto report = db::syncSpool(path, *server, &error);
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
