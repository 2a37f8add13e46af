#pragma once
// What `driftlab-cli batch` asks of each item (docs/batch.md): --what, and
// the arguments of the batch-item child that analyses one item. The items
// themselves are db/BatchItems', the analyses db/BatchAnalysis'.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QStringList>

#include "db/BatchAnalysis.h"
#include "db/BatchItems.h"

namespace driftlab::cli {

using db::BatchItem;
using db::FoundItems;

/// --what LIST (default: every analysis).
QCommandLineOption analysesOption();
/// The analyses --what asks for; throws CliError (exit 2) naming one that is unknown.
QStringList analysesAsked(const QCommandLineParser& parser);
/// The campaign for batch-item: {--, PATH} or {--db, FILE, --campaign, ID}.
QStringList batchItemSource(const BatchItem& item);

}  // namespace driftlab::cli
