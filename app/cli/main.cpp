// driftlab-cli: the headless DriftLab. Progress on stderr, results on stdout
// (JSON with --json), non-zero exit and a one-line reason on failure.
#include <glog/logging.h>

#include <QApplication>

#include <cstdio>

#include "app/cli/CliCommon.h"
#include "app/cli/CommandTable.h"
#include "core/domain/ServiceError.h"

namespace {

using namespace driftlab::cli;

/// The usage on stderr and, as its last line, why the command line was refused.
int refuseCommandLine(const QString& why) {
    std::fputs(qPrintable(usageText()), stderr);
    std::fprintf(stderr, "\ndriftlab-cli: %s\n", qPrintable(why));
    return kExitUsage;
}

QString unknownCommandReason(const QString& name) {
    if (name.startsWith(QLatin1Char('-')))
        return QStringLiteral("unknown option '%1' (a COMMAND comes first, its options after it)")
            .arg(name);
    const QString near = closestCommand(name);
    return near.isEmpty()
               ? QStringLiteral("unknown command '%1'").arg(name)
               : QStringLiteral("unknown command '%1' (did you mean '%2'?)").arg(name, near);
}

/// Runs one command: `args` from the command name on.
int runCommand(const Command& command, const QStringList& args) {
    if (!command.run) {
        // Exit 3, not the usage: the command line is right, this version lacks the command.
        std::fprintf(stderr, "driftlab-cli %s: %s\n", qPrintable(command.name),
                     qPrintable(notBuiltReason()));
        return kExitNotBuilt;
    }
    try {
        return command.run(args);
    } catch (const CliError& e) {
        endProgressLine();
        if (e.exitCode != kExitOk)
            std::fprintf(stderr, "driftlab-cli %s: %s\n", qPrintable(command.name), e.what());
        return e.exitCode;
    } catch (const driftlab::ServiceError& e) {
        // A library's service: a bad request is a usage error, like CliError's exit 2.
        endProgressLine();
        std::fprintf(stderr, "driftlab-cli %s: %s\n", qPrintable(command.name), e.what());
        return e.kind == driftlab::ServiceError::Kind::BadRequest ? kExitUsage : kExitFailure;
    }
}

int dispatch(const QStringList& args) {
    if (args.isEmpty()) return refuseCommandLine(QStringLiteral("a command is needed"));
    const QString& first = args.front();
    if (first == QLatin1String("--version")) {
        std::printf("driftlab-cli %s\n", DRIFTLAB_VERSION);
        return kExitOk;
    }
    // Help that was asked for is the answer, so it goes to stdout with success.
    if (first == QLatin1String("--help") || first == QLatin1String("-h") ||
        (first == QLatin1String("help") && args.size() == 1)) {
        std::fputs(qPrintable(usageText()), stdout);
        return kExitOk;
    }
    if (first == QLatin1String("help")) {
        if (args.size() > 2) return refuseCommandLine(QStringLiteral("help takes one COMMAND"));
        const Command* command = findCommand(args[1]);
        if (!command) return refuseCommandLine(unknownCommandReason(args[1]));
        return runCommand(*command, {command->name, QStringLiteral("--help")});
    }
    const Command* command = findCommand(first);
    if (!command) return refuseCommandLine(unknownCommandReason(first));
    return runCommand(*command, args);
}

}  // namespace

int main(int argc, char** argv) {
    // Plots are rendered offscreen; the CLI never opens a window.
    prepareHeadlessQt();
    QApplication app(argc, argv);
    // Ceres logs through glog; what matters reaches the user as our own
    // one-line reasons and fit notes, so only fatal glog messages show.
    FLAGS_minloglevel = google::GLOG_FATAL;
    QCoreApplication::setApplicationName(QStringLiteral("driftlab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIFTLAB_VERSION));
    return dispatch(app.arguments().mid(1));
}
