#include "app/cli/BatchItems.h"

#include "app/cli/CliCommon.h"

namespace driftlab::cli {

QCommandLineOption analysesOption() {
    const QString all = db::batchAnalyses().join(QLatin1Char(','));
    return {QStringLiteral("what"),
            QStringLiteral("Analyses per campaign, comma-separated: %1 (default: all; diagnose "
                           "is the slow one).")
                .arg(all),
            QStringLiteral("LIST"), all};
}

QStringList analysesAsked(const QCommandLineParser& parser) {
    const QStringList known = db::batchAnalyses();
    const QStringList asked = runList(parser.value(QStringLiteral("what")));
    if (asked.isEmpty())
        throw CliError(
            QStringLiteral("--what: name at least one of %1").arg(known.join(QStringLiteral(", "))),
            2);
    for (const QString& name : asked)
        if (!known.contains(name))
            throw CliError(QStringLiteral("--what: '%1' is not an analysis (%2)")
                               .arg(name, known.join(QStringLiteral(", "))),
                           2);
    return asked;
}

QStringList batchItemSource(const BatchItem& item) {
    if (item.campaign.isEmpty()) return {QStringLiteral("--"), item.path};
    return {QStringLiteral("--db"), item.path, QStringLiteral("--campaign"), item.campaign};
}

}  // namespace driftlab::cli
