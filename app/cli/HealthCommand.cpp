// health: sensor self-diagnosis of a campaign's logged samples (DESIGN.md §7,
// docs/sensor-health.md): per run and channel, what was found (out of range,
// frozen, spikes, rate of change, redundant drift), how many samples and when.
// Findings are results, not failures: the exit code is 0 either way and
// `healthy` in the JSON says whether anything was found.
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "core/sensors/SensorHealth.h"

namespace driftlab::cli {
namespace {

std::vector<sensors::RedundantPair> redundantPairs(const QStringList& values) {
    std::vector<sensors::RedundantPair> pairs;
    for (const QString& value : values) {
        const QStringList two = value.split(QLatin1Char('='));
        if (two.size() != 2 || two[0].isEmpty() || two[1].isEmpty())
            throw CliError(QStringLiteral("--redundant: '%1' is not two channels, A=B").arg(value),
                           2);
        pairs.push_back({two[0], two[1]});
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
    parseArguments(parser, args, campaignSourceOptions() << runs << redundant,
                   campaignSourceArguments());
    const auto pairs = redundantPairs(parser.values(redundant));
    const QStringList wanted = runList(parser.value(runs));
    const Campaign campaign = loadCampaignSource(parser);
    for (const QString& id : wanted) {
        if (std::none_of(campaign.runs.begin(), campaign.runs.end(),
                         [&](const Run& r) { return r.id == id; }))
            throw CliError(QStringLiteral("--run: the campaign has no run '%1'").arg(id), 2);
    }
    const sensors::SensorHealthSettings settings;
    bool healthy = true;
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
        runsJson.append(
            QJsonObject{{QStringLiteral("id"), run.id}, {QStringLiteral("channels"), channels}});
    }
    if (parser.isSet(QStringLiteral("json"))) {
        printJson({{QStringLiteral("healthy"), healthy}, {QStringLiteral("runs"), runsJson}});
        return 0;
    }
    for (const QString& line : lines) printLine(line);
    return 0;
}

}  // namespace driftlab::cli
