// batch: many campaigns analysed at once (docs/batch.md).
// One JSON line per item on stdout, in the order of the items (the PATHs as
// given, a searched folder's finds by path), so that two runs can be diffed
// whatever -j was; progress on stderr; exit 1 when any item failed.
#include <QJsonObject>
#include <QThread>
#include <cstdio>
#include <optional>

#include "app/cli/BatchItems.h"
#include "app/cli/BatchRunner.h"
#include "app/cli/CliCommon.h"
#include "app/cli/CommandTable.h"
#include "app/cli/FlaggedSamples.h"

namespace driftlab::cli {
namespace {

int jobsOption(const QCommandLineParser& parser, const QCommandLineOption& option) {
    if (!parser.isSet(option)) return std::max(1, QThread::idealThreadCount());
    bool ok = false;
    const int jobs = parser.value(option).toInt(&ok);
    if (!ok || jobs < 1)
        throw CliError(QStringLiteral("-j: '%1' is not a whole number of at least 1")
                           .arg(parser.value(option)),
                       2);
    return jobs;
}

}  // namespace

int batchCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption jobs{{QStringLiteral("j"), QStringLiteral("jobs")},
                                  QStringLiteral("Campaigns analysed at once, each in its own "
                                                 "process (default: the number of cores)."),
                                  QStringLiteral("N")};
    const QCommandLineOption timeout{
        QStringLiteral("timeout-s"),
        QStringLiteral("An item still running after S seconds is stopped and reported as "
                       "failed (default 3600)."),
        QStringLiteral("S"), QStringLiteral("3600")};
    const QCommandLineOption memory{
        QStringLiteral("memory-mb"),
        QStringLiteral("Address space each item may use, in MiB; an item that needs more fails "
                       "alone (default: no limit)."),
        QStringLiteral("MB")};
    parseArguments(parser, args, {jobs, analysesOption(), timeout, memory, keepFlaggedOption()},
                   {QStringLiteral("PATH..."),
                    QStringLiteral("A campaign bundle folder, a .zip bundle, a DriftLab store "
                                   "(each campaign in it; FILE#ID for one), or a folder searched "
                                   "for them."),
                    QStringLiteral("PATH"),
                    {}});
    if (parser.positionalArguments().isEmpty())
        throw CliError(QStringLiteral("give at least one PATH"), 2);
    BatchRunOptions options;
    options.jobs = jobsOption(parser, jobs);
    options.timeout_s = positiveNumberOption(parser, timeout);
    if (parser.isSet(memory)) options.memory_mb = positiveNumberOption(parser, memory);
    const QStringList what = analysesAsked(parser);
    options.itemArguments << QStringLiteral("--what") << what.join(QLatin1Char(','));
    if (parser.isSet(QStringLiteral("keep-flagged")))
        options.itemArguments << QStringLiteral("--keep-flagged");

    const FoundItems found = db::findBatchItems(parser.positionalArguments());
    for (const QString& note : found.notes) std::fprintf(stderr, "batch: %s\n", qPrintable(note));
    const std::size_t total = found.items.size();
    std::fprintf(stderr, "batch: %zu item%s, %d at a time\n", total, total == 1 ? "" : "s",
                 options.jobs);

    // Lines are held back until every item before them is done: input order.
    std::vector<std::optional<QJsonObject>> lines(total);
    std::size_t nextToPrint = 0, done = 0, failed = 0;
    runBatch(found.items, options, [&](std::size_t index, const QJsonObject& line) {
        ++done;
        if (!line[QStringLiteral("ok")].toBool()) ++failed;
        lines[index] = line;
        while (nextToPrint < total && lines[nextToPrint]) {
            printJson(*lines[nextToPrint]);
            lines[nextToPrint++].reset();
        }
        std::fflush(stdout);
        std::fprintf(stderr, "batch: %zu of %zu done, %zu failed\n", done, total, failed);
    });
    if (failed > 0)
        throw CliError(QStringLiteral("%1 of %2 item%3 failed (their lines say why)")
                           .arg(failed)
                           .arg(total)
                           .arg(total == 1 ? "" : "s"));
    return kExitOk;
}

}  // namespace driftlab::cli
