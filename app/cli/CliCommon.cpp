#include "app/cli/CliCommon.h"

#include <unistd.h>
#include <QJsonDocument>
#include <cmath>
#include <cstdio>

#include "core/bundle/BundleReader.h"
#include "db/CampaignStore.h"
#include "db/ZipBundleSource.h"

namespace driftlab::cli {

void parseArguments(QCommandLineParser& parser, const QStringList& args,
                    const QList<QCommandLineOption>& options, const QString& positional) {
    parser.addHelpOption();
    parser.addOption(
        {QStringLiteral("json"), QStringLiteral("Print the result as JSON on stdout.")});
    parser.addOptions(options);
    if (!positional.isEmpty()) parser.addPositionalArgument(positional, positional);
    if (!parser.parse(args)) throw CliError(parser.errorText(), 2);
    if (parser.isSet(QStringLiteral("help"))) {
        std::fputs(qPrintable(parser.helpText()), stdout);
        throw CliError(QString(), 0);
    }
}

QList<QCommandLineOption> campaignSourceOptions() {
    return {{QStringLiteral("db"), QStringLiteral("Campaign database (SQLite file)."),
             QStringLiteral("FILE")},
            {QStringLiteral("campaign"), QStringLiteral("Campaign id in the database."),
             QStringLiteral("ID")}};
}

Campaign loadCampaignSource(const QCommandLineParser& parser, db::StoreAccess access) {
    const QStringList positional = parser.positionalArguments();
    if (parser.isSet(QStringLiteral("db"))) {
        bool ok = false;
        const qint64 id = parser.value(QStringLiteral("campaign")).toLongLong(&ok);
        if (!ok) throw CliError(QStringLiteral("--db needs --campaign ID (a number)"), 2);
        auto store = openSourceStore(parser, access);
        QString error;
        auto campaign = store->loadCampaign(id, &error);
        if (!campaign) throw CliError(error);
        return *campaign;
    }
    if (positional.size() != 1)
        throw CliError(QStringLiteral("give a BUNDLE folder or --db FILE --campaign ID"), 2);
    return readBundleOrFail(positional.front());
}

std::unique_ptr<db::CampaignStore> openSourceStore(const QCommandLineParser& parser,
                                                   db::StoreAccess access) {
    QString error;
    auto store = db::CampaignStore::open(parser.value(QStringLiteral("db")), access, &error);
    if (!store) throw CliError(error);
    return store;
}

std::optional<qint64> storeFitIfFromDatabase(const QCommandLineParser& parser,
                                             const db::ModelFitRecord& record) {
    if (!parser.isSet(QStringLiteral("db"))) return std::nullopt;
    auto store = openSourceStore(parser, db::StoreAccess::ReadWrite);
    QString error;
    auto id = db::storeModelFit(*store, parser.value(QStringLiteral("campaign")).toLongLong(),
                                record, &error);
    if (!id) throw CliError(error);
    return id;
}

std::unique_ptr<BundleSource> openBundleOrFail(const QString& path) {
    QString error;
    auto source = db::openBundleSource(path, &error);
    if (!source) throw CliError(path + QStringLiteral(": ") + error);
    return source;
}

void printWarnings(const QStringList& warnings) {
    endProgressLine();
    for (const QString& warning : warnings)
        std::fprintf(stderr, "warning: %s\n", qPrintable(warning));
}

Campaign readBundleOrFail(const QString& path) {
    const auto source = openBundleOrFail(path);
    BundleReadOptions options;
    options.progress = [](double f) { return printProgress(QStringLiteral("reading bundle"), f); };
    BundleReadResult result = readBundle(*source, options);
    printWarnings(result.warnings);
    if (!result.ok()) {
        // Name the file by its full path so the user can open it at that line.
        BundleError e = *result.error;
        e.file = source->displayPath(e.file);
        throw CliError(e.toString());
    }
    return *result.campaign;
}

namespace {
bool g_progressLineOpen = false;
QString g_progressShown;  ///< "label: percent" last written, to rewrite only on change
}  // namespace

bool printProgress(const QString& label, double fraction) {
    const int percent = int(fraction * 100 + 0.5);
    // On a terminal the line is rewritten in place; in a log (CI, a script's
    // stderr) it grows by tens of per cent so the log stays readable.
    static const bool terminal = isatty(fileno(stderr));
    const int shownPercent = terminal ? percent : percent / 10 * 10;
    const QString shown = QStringLiteral("%1: %2%").arg(label).arg(shownPercent, 3);
    if (shown == g_progressShown) return true;
    const bool sameLabel = g_progressShown.startsWith(label + QLatin1Char(':'));
    g_progressShown = shown;
    if (terminal)
        std::fprintf(stderr, "\r%s", qPrintable(shown));
    else if (sameLabel && g_progressLineOpen)
        std::fprintf(stderr, " %d%%", shownPercent);
    else
        std::fprintf(stderr, "%s%s", g_progressLineOpen ? "\n" : "", qPrintable(shown));
    g_progressLineOpen = fraction < 1.0;
    if (!g_progressLineOpen) std::fputc('\n', stderr);
    return true;
}

void endProgressLine() {
    if (g_progressLineOpen) std::fputc('\n', stderr);
    g_progressLineOpen = false;
}

QJsonValue jsonNumber(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QStringList runList(const QString& text) {
    QStringList ids;
    for (const QString& id : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) ids << id.trimmed();
    return ids;
}

void printJson(const QJsonObject& object) {
    std::fputs(QJsonDocument(object).toJson(QJsonDocument::Compact).constData(), stdout);
    std::fputc('\n', stdout);
}

void printLine(const QString& text) {
    std::fputs(text.toUtf8().constData(), stdout);
    std::fputc('\n', stdout);
}

}  // namespace driftlab::cli
