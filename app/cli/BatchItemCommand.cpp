// batch-item: one campaign of `batch`, analysed in the child process that
// batch starts for it (docs/batch.md). It prints one JSON object on stdout:
// the campaign's name and runs and a key per analysis asked for
// (db/BatchAnalysis, shared with the GUI). An analysis that fails is null,
// its reason is "error" and the exit code is 1, with the other analyses'
// results kept. Nothing is written: a store is read with a read-only connection.
#include "app/cli/BatchItems.h"
#include "app/cli/CliCommon.h"
#include "app/cli/CommandTable.h"
#include "app/cli/FlaggedSamples.h"

namespace driftlab::cli {

int batchItemCommand(const QStringList& args) {
    QCommandLineParser parser;
    parseArguments(parser, args, campaignSourceOptions() << analysesOption() << keepFlaggedOption(),
                   campaignSourceArguments());
    db::BatchAnalysisOptions options;
    options.analyses = analysesAsked(parser);
    Campaign campaign = loadCampaignSource(parser, db::StoreAccess::ReadOnly);
    leaveOutFlaggedSamples(parser, campaign);
    const db::BatchAnalysis analysed = db::analyseCampaign(campaign, options);
    printJson(analysed.json);
    return analysed.ok() ? kExitOk : kExitFailure;
}

}  // namespace driftlab::cli
