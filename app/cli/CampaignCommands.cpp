// import, export and info: campaigns between bundles and the database.
#include <QFileInfo>
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "core/bundle/BundleWriter.h"
#include "db/AnalysisJson.h"
#include "db/CampaignImport.h"
#include "db/CampaignStore.h"
#include "db/StoreBackend.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kDbOption{
    QStringLiteral("db"),
    QStringLiteral("Campaign store: a SQLite file, or postgresql://USER@HOST[:PORT]/DB "
                   "for a store on a PostgreSQL server."),
    QStringLiteral("FILE")};

/// The --db store to import into; a missing one is created, visible only once published.
std::unique_ptr<db::CampaignStore> openStore(const QCommandLineParser& parser) {
    QString error;
    auto store =
        db::CampaignStore::open(parser.value(kDbOption), db::StoreAccess::CreateIfMissing, &error);
    if (!store) throw CliError(error);
    return store;
}

}  // namespace

int importCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption again{
        QStringLiteral("again"),
        QStringLiteral("Import a bundle whose content the store already holds once more.")};
    parseArguments(
        parser, args, {kDbOption, again},
        {QStringLiteral("BUNDLE"), bundleDescription(), QStringLiteral("BUNDLE"), {kDbOption}});
    if (parser.positionalArguments().size() != 1)
        throw CliError(QStringLiteral("give one BUNDLE folder or .zip"), 2);
    if (!parser.isSet(kDbOption)) throw CliError(QStringLiteral("--db FILE is required"), 2);
    const QString dbPath = parser.value(kDbOption);
    const auto source = openBundleOrFail(parser.positionalArguments().front());
    // Pass 1, before the store is touched: the whole bundle validated (rows
    // discarded as read) and hashed. A bad or repeated bundle leaves the store
    // byte for byte as it was, and a store that does not exist is not created.
    const db::BundleCheck checked = db::checkBundle(
        *source, [](double f) { return printProgress(QStringLiteral("checking bundle"), f); });
    printWarnings(checked.warnings);
    if (!checked.ok()) throw CliError(checked.error);
    if (!parser.isSet(again) && (db::isServerStoreUrl(dbPath) || QFileInfo::exists(dbPath))) {
        QString error;
        // A store that cannot be read here is refused below, with the writer's reason.
        if (auto reader = db::CampaignStore::open(dbPath, db::StoreAccess::ReadOnly, &error))
            if (auto why = db::alreadyImported(*reader, *source, checked)) throw CliError(*why);
    }
    // Pass 2: streamed into the store in one transaction; a new store becomes
    // visible under its name only once the import committed.
    auto store = openStore(parser);
    db::BundleImportOptions options;
    options.progress = [](double f) { return printProgress(QStringLiteral("importing"), f); };
    options.again = parser.isSet(again);
    const db::BundleImportResult result = db::importBundle(*store, *source, checked, options);
    QString error = result.error;
    if (!result.campaignId || !store->publish(&error)) throw CliError(error);
    if (parser.isSet(QStringLiteral("json")))
        printJson({{QStringLiteral("campaign"), *result.campaignId},
                   {QStringLiteral("name"), checked.name},
                   {QStringLiteral("content_sha256"), QString::fromLatin1(checked.contentSha256)},
                   {QStringLiteral("warnings"), QJsonArray::fromStringList(checked.warnings)}});
    else
        printLine(QString::number(*result.campaignId));
    return 0;
}

int exportCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption out{QStringLiteral("out"),
                                 QStringLiteral("Bundle folder to write (new or empty)."),
                                 QStringLiteral("DIR")};
    const QCommandLineOption force{
        QStringLiteral("force"),
        QStringLiteral("Replace a previous bundle in DIR as a whole (never a mix of two).")};
    const QList<QCommandLineOption> required = campaignSourceOptions() << out;
    // The campaign comes from a database, never a bundle: --db, --campaign and --out are required.
    parseArguments(parser, args, QList<QCommandLineOption>(required) << force,
                   {{}, {}, {}, required});
    const Campaign campaign = loadCampaignSource(parser);
    if (auto error = bundle::writeBundle(
            campaign, parser.value(out),
            parser.isSet(force) ? bundle::ExistingBundle::Replace : bundle::ExistingBundle::Refuse))
        throw CliError(error->toString());
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

    const QJsonObject info = db::campaignInfoJson(c);
    if (parser.isSet(QStringLiteral("json"))) {
        printJson(info);
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
    for (const QJsonValue& v : info[QStringLiteral("runs")].toArray()) {
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
