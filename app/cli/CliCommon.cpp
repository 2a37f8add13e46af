#include "app/cli/CliCommon.h"

#include <QSaveFile>

#include "app/cli/CommandTable.h"

#include <unistd.h>
#include <QJsonDocument>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/bundle/BundleReader.h"
#include "core/iso/PositioningRuns.h"
#include "db/CampaignStore.h"
#include "db/StoreBackend.h"
#include "db/ZipBundleSource.h"

namespace driftlab::cli {

namespace {

/// "--db FILE": an option as a user types it.
QString optionSyntax(const QCommandLineOption& option) {
    QString text = QStringLiteral("--") + option.names().constLast();
    if (!option.valueName().isEmpty()) text += QLatin1Char(' ') + option.valueName();
    return text;
}

}  // namespace

void parseArguments(QCommandLineParser& parser, const QStringList& args,
                    const QList<QCommandLineOption>& options, const Arguments& arguments) {
    const QString name = args.value(0);
    // Our own --help: Qt's addHelpOption() would add --help-all, which shows
    // Qt's generic options that driftlab-cli does not take.
    parser.addOption({{QStringLiteral("h"), QStringLiteral("help")},
                      QStringLiteral("Print this help on stdout.")});
    parser.addOption(
        {QStringLiteral("json"), QStringLiteral("Print the result as JSON on stdout.")});
    QStringList required;
    if (!arguments.positionalRequired.isEmpty()) required << arguments.positionalRequired;
    for (QCommandLineOption option : options) {
        const bool isRequired =
            std::any_of(arguments.required.begin(), arguments.required.end(),
                        [&](const QCommandLineOption& r) { return r.names() == option.names(); });
        if (isRequired) {
            option.setDescription(option.description() + QStringLiteral(" (required)"));
            required << optionSyntax(option);
        }
        parser.addOption(option);
    }
    if (!arguments.positional.isEmpty())
        parser.addPositionalArgument(arguments.positional, arguments.positionalHelp,
                                     arguments.positional);
    const Command* command = findCommand(name);
    QString description = command ? command->summary : QString();
    if (!required.isEmpty())
        description += QStringLiteral("\nRequired: ") + required.join(QStringLiteral(", "));
    parser.setApplicationDescription(description);

    if (!parser.parse(args)) throw CliError(parser.errorText(), 2);
    if (parser.isSet(QStringLiteral("help"))) {
        // Qt's usage line names the executable as it was started (a path) and
        // not the command; the command's own usage replaces it.
        QString help = parser.helpText();
        help.remove(0, help.indexOf(QLatin1Char('\n')));
        help.prepend(QStringLiteral("Usage: driftlab-cli %1 [options]%2")
                         .arg(name, arguments.positional.isEmpty()
                                        ? QString()
                                        : QLatin1Char(' ') + arguments.positional));
        std::fputs(qPrintable(help), stdout);
        throw CliError(QString(), 0);
    }
    for (const QCommandLineOption& option : arguments.required)
        if (!parser.isSet(option))
            throw CliError(QStringLiteral("%1 is required").arg(optionSyntax(option)), 2);
    // A server store's URL is read here, for every option that takes one, so
    // that a bad one is a usage error naming the option before anything runs.
    for (const QCommandLineOption& option : options) {
        for (const QString& value : parser.values(option)) {
            QString why;
            if (db::isServerStoreUrl(value) && !db::parseServerStoreUrl(value, &why))
                throw CliError(QStringLiteral("--%1: %2").arg(option.names().constLast(), why), 2);
        }
    }
}

QString bundleDescription() {
    return QStringLiteral(
        "Campaign bundle: a folder or a .zip of one (campaign.json, samples.csv, ...).");
}

QList<QCommandLineOption> campaignSourceOptions() {
    return {{QStringLiteral("db"),
             QStringLiteral("Campaign store: a SQLite file, or postgresql://USER@HOST[:PORT]/DB "
                            "for a store on a PostgreSQL server."),
             QStringLiteral("FILE")},
            {QStringLiteral("campaign"), QStringLiteral("Campaign id in the database."),
             QStringLiteral("ID")}};
}

Arguments campaignSourceArguments(const QList<QCommandLineOption>& required) {
    return {QStringLiteral("BUNDLE"), bundleDescription(),
            QStringLiteral("BUNDLE (or --db FILE --campaign ID)"), required};
}

void refuseOverlappingRuns(const QStringList& train, const QStringList& test) {
    QStringList both;
    for (const QString& id : train)
        if (test.contains(id) && !both.contains(id)) both << id;
    if (both.isEmpty()) return;
    const QString why = QStringLiteral("a held-out score needs runs the model has not seen");
    throw CliError(
        both.size() == 1
            ? QStringLiteral("run %1 is both a training and a test run: %2").arg(both.front(), why)
            : QStringLiteral("runs %1 are both training and test runs: %2")
                  .arg(both.join(QStringLiteral(", ")), why),
        2);
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

std::unique_ptr<bundle::BundleSource> openBundleOrFail(const QString& path) {
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
    bundle::BundleReadOptions options;
    options.progress = [](double f) { return printProgress(QStringLiteral("reading bundle"), f); };
    bundle::BundleReadResult result = bundle::readBundle(*source, options);
    printWarnings(result.warnings);
    if (!result.ok()) {
        // Name the file by its full path so the user can open it at that line.
        bundle::BundleError e = *result.error;
        e.file = source->displayPath(e.file);
        throw CliError(e.toString());
    }
    return *result.campaign;
}

double numberOption(const QCommandLineParser& parser, const QCommandLineOption& option) {
    bool ok = false;
    const double value = parser.value(option).toDouble(&ok);
    if (!ok || !std::isfinite(value))
        throw CliError(QStringLiteral("--%1: '%2' is not a number")
                           .arg(option.names().front(), parser.value(option)),
                       2);
    return value;
}

double positiveNumberOption(const QCommandLineParser& parser, const QCommandLineOption& option) {
    const double value = numberOption(parser, option);
    if (value <= 0)
        throw CliError(QStringLiteral("--%1: '%2' is not a positive number")
                           .arg(option.names().front(), parser.value(option)),
                       2);
    return value;
}

QJsonValue jsonNumber(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QStringList runList(const QString& text) {
    QStringList ids;
    for (const QString& id : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) ids << id.trimmed();
    return ids;
}

void writeFileAtomically(const QString& path, const QByteArray& text) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit())
        throw CliError(QStringLiteral("%1: cannot write: %2").arg(path, file.errorString()));
}

const Run& choosePositioningRun(const Campaign& campaign, const QString& wanted) {
    const iso::PositioningRunChoice choice = iso::choosePositioningRun(campaign, wanted);
    if (!choice.run) throw CliError(choice.error, choice.usage ? 2 : 1);
    return *choice.run;
}

QString umText(double value_um) {
    return std::isfinite(value_um) ? QString::number(value_um, 'f', 3) : QStringLiteral("n/a");
}

}  // namespace driftlab::cli
