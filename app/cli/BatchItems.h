#pragma once
// The items of `driftlab-cli batch` and what is asked of each (docs/batch.md):
// the PATHs given, turned into one item per campaign — a bundle folder, a
// zipped bundle, each campaign of a DriftLab store (FILE#ID) — with folders
// that are none of these searched for them.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>
#include <vector>

namespace driftlab::cli {

/// The analyses batch runs, as --what names them.
inline const QString kAnalysisInfo = QStringLiteral("info");
inline const QString kAnalysisIso230_2 = QStringLiteral("iso230-2");
inline const QString kAnalysisFit = QStringLiteral("fit");
inline const QString kAnalysisDiagnose = QStringLiteral("diagnose");

/// --what LIST (default: every analysis).
QCommandLineOption analysesOption();
/// The analyses --what asks for; throws CliError (exit 2) naming one that is unknown.
QStringList analysesAsked(const QCommandLineParser& parser);
/// The JSON key of an analysis's result: "iso230_2", "fit", "diagnosis".
QString analysisKey(const QString& analysis);

struct BatchItem {
    QString item;  ///< as reported: the path, or FILE#ID for a campaign of a store
    QStringList
        source;     ///< the campaign for batch-item: {--, PATH} or {--db, FILE, --campaign, ID}
    QString error;  ///< set: the item failed before it could be analysed (e.g. no such path)
};

struct FoundItems {
    std::vector<BatchItem> items;  ///< in the order of the PATHs; a folder's found items by path
    QStringList notes;             ///< files a search passed over, and why (for stderr)
};

/// The items of `paths`, each path being a bundle folder, a .zip bundle, a
/// store file (every campaign in it), FILE#ID (one campaign of a store), or a
/// folder searched recursively for those (a bundle folder is not searched
/// inside). A path that does not exist, a store that cannot be read or a
/// folder with nothing in it is an item with its error, not an exception.
FoundItems findBatchItems(const QStringList& paths);

}  // namespace driftlab::cli
