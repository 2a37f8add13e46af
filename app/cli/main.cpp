// driftlab-cli: the headless DriftLab. Progress on stderr, results on stdout
// (JSON with --json), non-zero exit and a one-line reason on failure.
#include <glog/logging.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QApplication>

#include <cstdio>
#include <functional>
#include <map>

#include "app/cli/CliCommon.h"

namespace driftlab::cli {
int importCommand(const QStringList& args);
int exportCommand(const QStringList& args);
int infoCommand(const QStringList& args);
int simulateCommand(const QStringList& args);
int fitCommand(const QStringList& args);
int compareCommand(const QStringList& args);
int benchCommand(const QStringList& args);
int diagnoseCommand(const QStringList& args);
}  // namespace driftlab::cli

int main(int argc, char** argv) {
    // Plots are rendered offscreen; the CLI never opens a window.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    // Qt wants a private runtime folder; make it as Qt would, without its warning.
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QByteArray runtime = QByteArray("/tmp/runtime-") + QByteArray::number(getuid());
        mkdir(runtime.constData(), 0700);
        qputenv("XDG_RUNTIME_DIR", runtime);
    }
    QApplication app(argc, argv);
    // Ceres logs through glog; what matters reaches the user as our own
    // one-line reasons and fit notes, so only fatal glog messages show.
    FLAGS_minloglevel = google::GLOG_FATAL;
    QCoreApplication::setApplicationName(QStringLiteral("driftlab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIFTLAB_VERSION));
    using namespace driftlab::cli;
    const std::map<QString, std::pair<std::function<int(const QStringList&)>, const char*>>
        commands{
            {QStringLiteral("import"),
             {importCommand, "import BUNDLE --db FILE     store a bundle (one transaction)"}},
            {QStringLiteral("export"),
             {exportCommand, "export --db FILE --campaign ID --out DIR   write a bundle back"}},
            {QStringLiteral("info"),
             {infoCommand, "info BUNDLE                 runs, channels, counts"}},
            {QStringLiteral("simulate"),
             {simulateCommand,
              "simulate --out DIR [--effect ID=VALUE]... [--seed N]   a campaign from the rig"}},
            {QStringLiteral("fit"),
             {fitCommand, "fit BUNDLE --model NAME [--train R,..] [--test R,..] [--target CH]"}},
            {QStringLiteral("compare"),
             {compareCommand, "compare BUNDLE              every model, cross-state matrix"}},
            {QStringLiteral("diagnose"),
             {diagnoseCommand,
              "diagnose BUNDLE [--train R,.. --test R,..]   what the model misses, why"}},
            {QStringLiteral("bench"),
             {benchCommand, "bench [--json]              the performance figures of this machine"}},
        };
    QStringList args = app.arguments();
    if (args.size() < 2 || !commands.count(args[1])) {
        std::fprintf(stderr,
                     "usage: driftlab-cli COMMAND [options]  (COMMAND --help for its options)\n");
        for (const auto& [name, command] : commands) std::fprintf(stderr, "  %s\n", command.second);
        return args.size() >= 2 && args[1] == QLatin1String("--help") ? 0 : 2;
    }
    try {
        return commands.at(args[1]).first(args.mid(1));
    } catch (const CliError& e) {
        endProgressLine();
        if (e.exitCode != 0)
            std::fprintf(stderr, "driftlab-cli %s: %s\n", qPrintable(args[1]), e.what());
        return e.exitCode;
    }
}
