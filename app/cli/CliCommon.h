#pragma once
// What every driftlab-cli command shares: argument parsing, where a campaign
// comes from (a bundle folder or --db FILE --campaign ID), JSON on stdout,
// progress on stderr and a one-line reason on failure.

#include <QCommandLineParser>
#include <QJsonObject>
#include <QStringList>
#include <stdexcept>
#include <vector>

#include "app/cli/ConsoleOutput.h"
#include "core/bundle/BundleSource.h"
#include "core/domain/Campaign.h"
#include "db/ModelFitStore.h"

namespace driftlab::cli {

/// What a command takes besides its optional options, for its --help and checks.
struct Arguments {
    QString positional;      ///< its syntax, e.g. "BUNDLE"; empty when it takes none
    QString positionalHelp;  ///< what it is, e.g. "campaign bundle folder"
    /// How the positional is required, for the "Required:" line (empty: not required).
    QString positionalRequired;
    QList<QCommandLineOption> required;  ///< options refused (exit 2) when missing
};

/// A parser with --help, --json and the given options; parses `args` (the
/// command name first) and throws CliError(…, 2) on a usage error or a
/// missing required option. --help prints the command's help on stdout and
/// throws CliError(…, 0).
void parseArguments(QCommandLineParser& parser, const QStringList& args,
                    const QList<QCommandLineOption>& options, const Arguments& arguments = {});

/// What a campaign bundle is, wherever a BUNDLE is taken.
QString bundleDescription();
/// --db FILE and --campaign ID, for commands that take a BUNDLE.
QList<QCommandLineOption> campaignSourceOptions();
/// BUNDLE or --db FILE --campaign ID, with these options required as well.
Arguments campaignSourceArguments(const QList<QCommandLineOption>& required = {});
/// Refuses (exit 2) runs that are both training and test runs: a held-out
/// score of a model on runs it was fitted to would flatter it.
void refuseOverlappingRuns(const QStringList& train, const QStringList& test);
/// The campaign named by the positional BUNDLE or by --db/--campaign. Commands
/// that store results in the --db store load it with ReadWrite, so that a store
/// they cannot write is refused before the work, not after.
Campaign loadCampaignSource(const QCommandLineParser& parser,
                            db::StoreAccess access = db::StoreAccess::ReadOnly);
/// With --db: the database of the campaign, opened (throws CliError); never created.
std::unique_ptr<db::CampaignStore> openSourceStore(const QCommandLineParser& parser,
                                                   db::StoreAccess access);
/// Stores a fit when the campaign came from --db (opened ReadWrite); returns its id.
std::optional<qint64> storeFitIfFromDatabase(const QCommandLineParser& parser,
                                             const db::ModelFitRecord& record);

/// The run whose positioning readings a command uses: `wanted` (--run), else
/// the one positioning run, else the one run with readings; throws CliError
/// naming the runs when there is no such run or the choice is ambiguous.
const Run& choosePositioningRun(const Campaign& campaign, const QString& wanted);

/// A bundle folder or .zip archive; throws CliError naming the path and why.
std::unique_ptr<bundle::BundleSource> openBundleOrFail(const QString& path);
/// Reads and validates a bundle (folder or .zip); throws CliError with file:line:column: why.
Campaign readBundleOrFail(const QString& path);
/// "warning: ..." lines on stderr.
void printWarnings(const QStringList& warnings);

/// The value of a numeric option; throws CliError (exit 2) naming the option
/// when it is not a finite number, or (positiveNumber) not above zero.
double numberOption(const QCommandLineParser& parser, const QCommandLineOption& option);
double positiveNumberOption(const QCommandLineParser& parser, const QCommandLineOption& option);

/// NaN (not determined) is JSON null.
QJsonValue jsonNumber(double value);
/// "S1, S2,S3" → {S1, S2, S3}.
QStringList runList(const QString& text);

/// Writes `text` to `path` whole or not at all (QSaveFile): a controller's
/// file is either the old one or the new one, never half a table.
void writeFileAtomically(const QString& path, const QByteArray& text);

/// A figure in µm (or µrad) to three decimals, "n/a" where the data cannot give it.
QString umText(double value_um);

}  // namespace driftlab::cli
