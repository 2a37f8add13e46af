// health: sensor self-diagnosis of a campaign's logged samples (docs/sensor-health.md,
// docs/sensor-health.md): per run and channel, what was found (out of range,
// frozen, spikes, rate of change, redundant drift), how many samples and when.
// Findings are results, not failures: the exit code is 0 either way and
// `healthy` in the JSON says whether anything was found. With --store the
// findings of each checked run replace its flags in the --db store, where the
// model commands leave flagged samples out (app/cli/FlaggedSamples.h).
#include <QJsonArray>
#include <cstdio>

#include "app/cli/CliCommon.h"
#include "core/sensors/SampleFlags.h"
#include "core/sensors/SensorHealth.h"
#include "db/SampleFlagStore.h"

namespace driftlab::cli {
namespace {

std::vector<sensors::RedundantPair> redundantPairs(const QStringList& values) {
    std::vector<sensors::RedundantPair> pairs;
    for (const QString& value : values) {
        const auto pair = sensors::parseRedundantPair(value);
        if (!pair)
            throw CliError(QStringLiteral("--redundant: '%1' is not two channels, A=B").arg(value),
                           2);
        pairs.push_back(*pair);
    }
    return pairs;
}

QJsonObject summaryJson(const sensors::ChannelHealthSummary& summary) {
    QJsonArray findings;
    for (const sensors::FaultFinding& f : summary.findings) {
        QJsonArray ranges;
        for (const sensors::TimeRange& r : f.ranges) ranges.append(QJsonArray{r.from_s, r.to_s});
        findings.append(QJsonObject{{QStringLiteral("kind"), sensors::toString(f.fault)},
                                    {QStringLiteral("samples"), qint64(f.samples)},
                                    {QStringLiteral("ranges_s"), ranges}});
    }
    return {{QStringLiteral("id"), summary.channel},
            {QStringLiteral("samples"), qint64(summary.samples)},
            {QStringLiteral("findings"), findings}};
}

/// Replaces each checked run's flags in the --db store; says what it stored on stderr.
void storeFound(const QCommandLineParser& parser,
                const std::vector<std::pair<QString, std::vector<sensors::FlaggedRange>>>& found) {
    auto store = openSourceStore(parser, db::StoreAccess::ReadWrite);
    const qint64 campaignId = parser.value(QStringLiteral("campaign")).toLongLong();
    QString error;
    std::size_t ranges = 0;
    for (const auto& [run, flags] : found) {
        const auto runId = db::runDbId(*store, campaignId, run, &error);
        if (!runId || !db::replaceRunFlags(*store, *runId, flags, &error)) throw CliError(error);
        ranges += flags.size();
    }
    std::fprintf(stderr, "flags: %zu ranges stored for %zu runs in %s\n", ranges, found.size(),
                 qPrintable(store->path()));
}

}  // namespace

int healthCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption runs{QStringLiteral("run"),
                                  QStringLiteral("Runs to check (default: every run)."),
                                  QStringLiteral("R,..")};
    const QCommandLineOption redundant{
        QStringLiteral("redundant"),
        QStringLiteral("Two temperature channels at the same place, A=B (repeatable): their "
                       "slow divergence is checked."),
        QStringLiteral("A=B")};
    const QCommandLineOption store{
        QStringLiteral("store"),
        QStringLiteral("Store the findings as sensor flags of each checked run in the --db store "
                       "(replacing its earlier ones); the model commands leave flagged samples "
                       "out.")};
    parseArguments(parser, args, campaignSourceOptions() << runs << redundant << store,
                   campaignSourceArguments());
    const auto pairs = redundantPairs(parser.values(redundant));
    const QStringList wanted = runList(parser.value(runs));
    const bool storeFlags = parser.isSet(store);
    if (storeFlags && !parser.isSet(QStringLiteral("db")))
        throw CliError(QStringLiteral("--store writes into a store: give --db FILE --campaign ID"),
                       2);
    // Opened for writing from the start, so a store it cannot write is refused before the work.
    const Campaign campaign = loadCampaignSource(
        parser, storeFlags ? db::StoreAccess::ReadWrite : db::StoreAccess::ReadOnly);
    for (const QString& id : wanted) {
        if (std::none_of(campaign.runs.begin(), campaign.runs.end(),
                         [&](const Run& r) { return r.id == id; }))
            throw CliError(QStringLiteral("--run: the campaign has no run '%1'").arg(id), 2);
    }
    const sensors::SensorHealthSettings settings;
    bool healthy = true;
    std::vector<std::pair<QString, std::vector<sensors::FlaggedRange>>> found;
    QJsonArray runsJson;
    QStringList lines;
    for (const Run& run : campaign.runs) {
        if (!wanted.isEmpty() && !wanted.contains(run.id)) continue;
        std::map<QString, sensors::ChannelHealth> checked;
        try {
            checked = sensors::checkRun(run.samples, campaign.channels, pairs, settings);
        } catch (const std::invalid_argument& e) {
            throw CliError(
                QStringLiteral("run %1: %2").arg(run.id, QString::fromStdString(e.what())), 2);
        }
        QJsonArray channels;
        int findings = 0;
        for (const auto& [id, health] : checked) {
            channels.append(summaryJson(health.summary));
            if (health.summary.healthy()) continue;
            for (const QString& line :
                 health.summary.describe().split(QLatin1Char('\n'), Qt::SkipEmptyParts))
                lines << QStringLiteral("%1  %2").arg(run.id, line);
            findings += int(health.summary.findings.size());
        }
        if (findings == 0)
            lines << QStringLiteral("%1  %2 channels checked over %3 rows: nothing found")
                         .arg(run.id)
                         .arg(checked.size())
                         .arg(run.samples.rowCount());
        healthy &= findings == 0;
        found.emplace_back(run.id, sensors::flaggedRanges(checked));
        runsJson.append(
            QJsonObject{{QStringLiteral("id"), run.id}, {QStringLiteral("channels"), channels}});
    }
    if (storeFlags) storeFound(parser, found);
    if (parser.isSet(QStringLiteral("json"))) {
        printJson({{QStringLiteral("healthy"), healthy}, {QStringLiteral("runs"), runsJson}});
        return 0;
    }
    for (const QString& line : lines) printLine(line);
    return 0;
}

}  // namespace driftlab::cli
