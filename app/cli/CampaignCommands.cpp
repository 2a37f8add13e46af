// import, export and info: campaigns between bundles and the database.
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kDbOption{QStringLiteral("db"),
                                   QStringLiteral("Campaign database (SQLite file)."),
                                   QStringLiteral("FILE")};

std::unique_ptr<db::CampaignStore> openStore(const QCommandLineParser& parser) {
    QString error;
    auto store = db::CampaignStore::open(parser.value(kDbOption), &error);
    if (!store) throw CliError(error);
    return store;
}

}  // namespace

int importCommand(const QStringList& args) {
    QCommandLineParser parser;
    parseArguments(
        parser, args, {kDbOption},
        {QStringLiteral("BUNDLE"), bundleDescription(), QStringLiteral("BUNDLE"), {kDbOption}});
    if (parser.positionalArguments().size() != 1)
        throw CliError(QStringLiteral("give one BUNDLE folder"), 2);
    auto store = openStore(parser);
    // Read (and validate) the whole bundle before touching the database.
    const Campaign campaign = readBundleOrFail(parser.positionalArguments().front());
    QString error;
    auto id = store->importCampaign(
        campaign, &error, [](double f) { return printProgress(QStringLiteral("importing"), f); });
    if (!id) throw CliError(error);
    if (parser.isSet(QStringLiteral("json")))
        printJson({{QStringLiteral("campaign"), *id}, {QStringLiteral("name"), campaign.name}});
    else
        printLine(QString::number(*id));
    return 0;
}

int exportCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption out{QStringLiteral("out"), QStringLiteral("Bundle folder to write."),
                                 QStringLiteral("DIR")};
    const QList<QCommandLineOption> options = campaignSourceOptions() << out;
    // Every option is required: the campaign comes from a database, never a bundle.
    parseArguments(parser, args, options, {{}, {}, {}, options});
    const Campaign campaign = loadCampaignSource(parser);
    if (auto error = writeBundle(campaign, parser.value(out)))
        throw CliError(parser.value(out) + QLatin1Char('/') + error->toString());
    if (parser.isSet(QStringLiteral("json")))
        printJson(
            {{QStringLiteral("out"), parser.value(out)}, {QStringLiteral("name"), campaign.name}});
    else
        printLine(parser.value(out));
    return 0;
}

int infoCommand(const QStringList& args) {
    QCommandLineParser parser;
    parseArguments(parser, args, campaignSourceOptions(), campaignSourceArguments());
    const Campaign c = loadCampaignSource(parser);

    QJsonArray runs, channels;
    for (const Run& run : c.runs)
        runs.append(QJsonObject{
            {QStringLiteral("id"), run.id},
            {QStringLiteral("kind"), toString(run.kind)},
            {QStringLiteral("samples"), qint64(run.samples.presentValueCount())},
            {QStringLiteral("sample_times"), qint64(run.samples.rowCount())},
            {QStringLiteral("positioning"), qint64(run.positioning.size())},
            {QStringLiteral("motion_segments"), qint64(run.motion.size())},
            {QStringLiteral("duration_s"),
             run.samples.rowCount() ? run.samples.time_s.back() - run.samples.time_s.front()
                                    : 0.0}});
    for (const Channel& ch : c.channels)
        channels.append(QJsonObject{{QStringLiteral("id"), ch.id},
                                    {QStringLiteral("quantity"), toString(ch.quantity)},
                                    {QStringLiteral("role"), toString(ch.role)},
                                    {QStringLiteral("unit"), unitOf(ch.quantity)}});
    if (parser.isSet(QStringLiteral("json"))) {
        printJson({{QStringLiteral("name"), c.name},
                   {QStringLiteral("machine"), c.machine.name},
                   {QStringLiteral("axis"), c.machine.axis},
                   {QStringLiteral("runs"), runs},
                   {QStringLiteral("channels"), channels}});
        return 0;
    }
    printLine(QStringLiteral("%1 — %2, axis %3").arg(c.name, c.machine.name, c.machine.axis));
    if (c.screw)
        printLine(QStringLiteral("screw: %1 mm long, Ø%2 mm, lead %3 mm, %4")
                      .arg(c.screw->length_mm)
                      .arg(c.screw->diameter_mm)
                      .arg(c.screw->lead_mm)
                      .arg(c.screw->mounting));
    printLine(QStringLiteral("channels:"));
    for (const Channel& ch : c.channels)
        printLine(QStringLiteral("  %1  %2 (%3) %4")
                      .arg(ch.id, -18)
                      .arg(toString(ch.quantity), toString(ch.role), unitOf(ch.quantity)));
    printLine(QStringLiteral("runs:"));
    for (const QJsonValue& v : runs) {
        const QJsonObject r = v.toObject();
        printLine(QStringLiteral("  %1  %2  %3 samples at %4 times over %5 s, %6 positioning "
                                 "readings, %7 motion segments")
                      .arg(r[QStringLiteral("id")].toString(), -6)
                      .arg(r[QStringLiteral("kind")].toString(), -11)
                      .arg(r[QStringLiteral("samples")].toInteger())
                      .arg(r[QStringLiteral("sample_times")].toInteger())
                      .arg(r[QStringLiteral("duration_s")].toDouble())
                      .arg(r[QStringLiteral("positioning")].toInteger())
                      .arg(r[QStringLiteral("motion_segments")].toInteger()));
    }
    return 0;
}

}  // namespace driftlab::cli
