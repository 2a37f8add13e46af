// run: a test procedure on a rig, logged live into a store (DESIGN.md section 7).
// Progress on stderr, the campaign id on stdout; Ctrl-C aborts cleanly (the
// run is kept, marked interrupted, and `--resume RUN` continues it).
#include <QFileInfo>
#include <atomic>
#include <csignal>

#include "acquisition/engine/ProcedureEngine.h"
#include "acquisition/engine/SimulatedRig.h"
#include "app/cli/CliCommon.h"
#include "app/cli/RunRigs.h"

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
    const QCommandLineOption db{QStringLiteral("db"),
                                QStringLiteral("Store to log into (created when missing)."),
                                QStringLiteral("FILE")};
    const QCommandLineOption speedup{
        QStringLiteral("speedup"),
        QStringLiteral("Run time per wall-clock time on the simulated rig (0: as fast as it "
                       "goes)."),
        QStringLiteral("N"), QStringLiteral("0")};
    const QCommandLineOption resume{QStringLiteral("resume"),
                                    QStringLiteral("Continue the interrupted run with this id."),
                                    QStringLiteral("RUN")};
    parseArguments(
        parser, args,
        QList<QCommandLineOption>{procedure, rigOption, db, speedup, resume} + rigOptions(),
        {{}, {}, {}, {procedure, db}});

    QString error;
    const auto proc = procedures::loadProcedureFile(parser.value(procedure), &error);
    if (!proc) throw CliError(error, 2);
    engine::EngineOptions options;
    options.store_path = parser.value(db);
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

    engine::ProcedureEngine engine(*proc, *rig, options);
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
    QString lastRun;
    engine.setProgressCallback([&](const engine::EngineProgress& p) {
        if (g_stopRequested) engine.abort();
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
    if (engine.state() == engine::EngineState::Interrupted)
        fprintf(stderr,
                "run: aborted; the run is kept and marked interrupted "
                "(continue it with --resume)\n");
    if (parser.isSet(QStringLiteral("json")))
        printJson({{QStringLiteral("campaign"), *campaignId},
                   {QStringLiteral("state"), toString(engine.state())}});
    else
        printLine(QString::number(*campaignId));
    return engine.state() == engine::EngineState::Finished ? 0 : 3;
}

}  // namespace driftlab::cli
