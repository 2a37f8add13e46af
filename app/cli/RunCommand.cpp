// run: a test procedure on a rig, logged live into a store (docs/acquisition.md).
// Progress on stderr, the campaign id on stdout; Ctrl-C aborts cleanly (the
// run is kept, marked interrupted, and `--resume RUN` continues it). Into a
// server store it logs into a local spool that an uploader copies to the
// server as it goes (docs/lab-store.md).
#include <QFileInfo>
#include <atomic>
#include <csignal>

#include "acquisition/engine/ProcedureEngine.h"
#include "acquisition/engine/SimulatedRig.h"
#include "acquisition/logging/SpoolUploader.h"
#include "app/cli/CliCommon.h"
#include "app/cli/RunRigs.h"
#include "app/cli/SpoolCommands.h"
#include "db/CampaignStore.h"
#include "db/SpoolUpload.h"
#include "db/StoreBackend.h"

namespace driftlab::cli {
namespace {

std::atomic<bool> g_stopRequested{false};

extern "C" void requestStop(int) {
    g_stopRequested = true;
}

}  // namespace

int runCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption procedure{QStringLiteral("procedure"),
                                       QStringLiteral("Procedure file (JSON; shipped ones in "
                                                      "/usr/share/driftlab/procedures/ when "
                                                      "installed, resources/procedures/ in the "
                                                      "source)."),
                                       QStringLiteral("FILE")};
    const QCommandLineOption rigOption{
        QStringLiteral("rig"),
        QStringLiteral("sim (the simulated rig) or modbus://HOST:PORT (a temperature module; "
                       "see --device-map)."),
        QStringLiteral("RIG"), QStringLiteral("sim")};
    const QCommandLineOption db{
        QStringLiteral("db"),
        QStringLiteral("Store to log into: a SQLite file (created when missing), or "
                       "postgresql://USER@HOST[:PORT]/DB (logged into --spool and uploaded)."),
        QStringLiteral("FILE")};
    const QCommandLineOption spool = spoolOption();
    const QCommandLineOption uploadTimeout{
        QStringLiteral("upload-timeout"),
        QStringLiteral("With a server store: how long to keep trying to upload after the run "
                       "(s); what is not uploaded stays in the spool for `sync`."),
        QStringLiteral("S"), QStringLiteral("60")};
    const QCommandLineOption speedup{
        QStringLiteral("speedup"),
        QStringLiteral("Run time per wall-clock time on the simulated rig (0: as fast as it "
                       "goes)."),
        QStringLiteral("N"), QStringLiteral("0")};
    const QCommandLineOption unsaved{
        QStringLiteral("max-unsaved-rows"),
        QStringLiteral("While the store refuses writes (a full disk), how many rows to hold in "
                       "memory until space is freed; beyond them the run fails."),
        QStringLiteral("N"), QStringLiteral("1000000")};
    const QCommandLineOption resume{QStringLiteral("resume"),
                                    QStringLiteral("Continue the interrupted run with this id."),
                                    QStringLiteral("RUN")};
    parseArguments(parser, args,
                   QList<QCommandLineOption>{procedure, rigOption, db, spool, uploadTimeout,
                                             speedup, unsaved, resume} +
                       rigOptions(),
                   {{}, {}, {}, {procedure, db}});

    QString error;
    const auto proc = procedures::loadProcedureFile(parser.value(procedure), &error);
    if (!proc) throw CliError(error, 2);
    engine::EngineOptions options;
    options.store_path = parser.value(db);
    const QString serverUrl =
        db::isServerStoreUrl(options.store_path) ? options.store_path : QString();
    const double uploadTimeout_s = numberOption(parser, uploadTimeout);
    std::unique_ptr<logging::SpoolUploader> uploader;
    QString spoolId;
    if (!serverUrl.isEmpty()) {
        options.store_path = spoolPath(parser, spool);
        spoolId = prepareSpool(options.store_path);
        uploader = std::make_unique<logging::SpoolUploader>(
            options.store_path, spoolId, serverUrl,
            [](const QString& message) { std::fprintf(stderr, "%s\n", qPrintable(message)); });
    }
    options.max_unsaved_rows = qint64(positiveNumberOption(parser, unsaved));
    options.speedup = numberOption(parser, speedup);
    if (options.speedup < 0) throw CliError(QStringLiteral("--speedup: must be ≥ 0"), 2);
    if (parser.isSet(resume)) {
        bool ok = false;
        options.resume_run_id = parser.value(resume).toLongLong(&ok);
        if (!ok)
            throw CliError(QStringLiteral("--resume: '%1' is not a run id (see the progress "
                                          "lines of the run, or `info`)")
                               .arg(parser.value(resume)),
                           2);
    }
    std::unique_ptr<engine::TestRig> rig = makeRig(parser, parser.value(rigOption), *proc);

    options.stop_requested = &g_stopRequested;
    engine::ProcedureEngine engine(*proc, *rig, options);
    if (uploader) uploader->start();
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
    QString lastRun, storeProblem;
    engine.setProgressCallback([&](const engine::EngineProgress& p) {
        if (p.store_problem != storeProblem) {
            endProgressLine();
            if (!p.store_problem.isEmpty())
                std::fprintf(stderr,
                             "warning: %s; the rows from %g s on are kept in memory and saved "
                             "once the store takes them again: free space for it now\n",
                             qPrintable(p.store_problem), p.unsaved_since_s);
            else
                std::fprintf(stderr, "the store takes the rows again; none is lost\n");
            storeProblem = p.store_problem;
        }
        if (p.run != lastRun) {
            endProgressLine();
            lastRun = p.run;
        }
        printProgress(QStringLiteral("%1 (%2/%3, %4)")
                          .arg(p.run)
                          .arg(p.run_index + 1)
                          .arg(p.run_count)
                          .arg(toString(p.state)),
                      p.duration_s > 0 ? std::min(1.0, p.time_s / p.duration_s) : 0);
    });
    const auto campaignId = engine.run(&error);
    endProgressLine();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (!campaignId) throw CliError(error);
    std::optional<qint64> serverCampaignId;
    if (uploader) {
        std::fprintf(stderr, "uploading the spool to %s\n", qPrintable(serverUrl));
        const auto report = uploader->finish(uploadTimeout_s, &error);
        if (!report)
            throw CliError(QStringLiteral("%1; the run is kept in the spool %2 and "
                                          "`driftlab-cli sync --spool %2 --db %3` uploads it")
                               .arg(error, options.store_path, serverUrl));
        auto server = db::CampaignStore::open(serverUrl, db::StoreAccess::ReadOnly, &error);
        if (!server) throw CliError(error);
        serverCampaignId =
            db::uploadedId(*server, spoolId, QStringLiteral("campaign"), *campaignId);
        if (!serverCampaignId)
            throw CliError(QStringLiteral("%1: campaign %2 of the spool %3 is not there after "
                                          "the upload")
                               .arg(serverUrl)
                               .arg(*campaignId)
                               .arg(options.store_path));
    }
    if (engine.state() == engine::EngineState::Interrupted)
        fprintf(stderr,
                "run: aborted; the run is kept and marked interrupted "
                "(continue it with --resume)\n");
    if (parser.isSet(QStringLiteral("json"))) {
        QJsonObject result{{QStringLiteral("campaign"), serverCampaignId.value_or(*campaignId)},
                           {QStringLiteral("state"), toString(engine.state())}};
        if (uploader) {
            result[QStringLiteral("spool")] = options.store_path;
            result[QStringLiteral("spool_campaign")] = *campaignId;
        }
        printJson(result);
    } else
        printLine(QString::number(serverCampaignId.value_or(*campaignId)));
    return engine.state() == engine::EngineState::Finished ? 0 : 3;
}

}  // namespace driftlab::cli
