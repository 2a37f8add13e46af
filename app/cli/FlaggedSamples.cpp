#include "app/cli/FlaggedSamples.h"

#include <cstdio>

#include "app/cli/CliCommon.h"
#include "db/FlaggedSampleMask.h"

namespace driftlab::cli {

QCommandLineOption keepFlaggedOption() {
    return {QStringLiteral("keep-flagged"),
            QStringLiteral("Use the samples that `health --store` flagged in the --db store "
                           "(default: left out).")};
}

std::optional<db::MaskedSamples> leaveOutFlaggedSamples(const QCommandLineParser& parser,
                                                        Campaign& campaign) {
    if (!parser.isSet(QStringLiteral("db")) || parser.isSet(QStringLiteral("keep-flagged")))
        return std::nullopt;
    auto store = openSourceStore(parser, db::StoreAccess::ReadOnly);
    QString error;
    const auto masked = db::leaveOutFlaggedSamples(
        *store, parser.value(QStringLiteral("campaign")).toLongLong(), campaign, &error);
    if (!masked) throw CliError(error);
    if (!masked->flagged) return std::nullopt;
    const std::size_t samples = masked->samples;
    const QStringList& channels = masked->channels;
    endProgressLine();
    // Stretches kept on the sensor-health page are used and not counted here.
    const QString kept = masked->kept == 0 ? QString()
                         : masked->kept == 1
                             ? QStringLiteral(", 1 flagged stretch kept")
                             : QStringLiteral(", %1 flagged stretches kept").arg(masked->kept);
    std::fprintf(stderr,
                 "flags: %zu samples of %lld channel%s left out%s (--keep-flagged to use them)\n",
                 samples, static_cast<long long>(channels.size()), channels.size() == 1 ? "" : "s",
                 qPrintable(kept));
    return masked;
}

}  // namespace driftlab::cli
