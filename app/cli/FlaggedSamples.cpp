#include "app/cli/FlaggedSamples.h"

#include <cstdio>

#include "app/cli/CliCommon.h"
#include "db/SampleFlagStore.h"

namespace driftlab::cli {

QCommandLineOption keepFlaggedOption() {
    return {QStringLiteral("keep-flagged"),
            QStringLiteral("Use the samples that `health --store` flagged in the --db store "
                           "(default: left out).")};
}

void leaveOutFlaggedSamples(const QCommandLineParser& parser, Campaign& campaign) {
    if (!parser.isSet(QStringLiteral("db")) || parser.isSet(QStringLiteral("keep-flagged"))) return;
    auto store = openSourceStore(parser, db::StoreAccess::ReadOnly);
    QString error;
    const auto flags =
        db::loadSampleFlags(*store, parser.value(QStringLiteral("campaign")).toLongLong(), &error);
    if (!flags) throw CliError(error);
    if (flags->empty()) return;
    std::size_t samples = 0;
    QStringList channels;
    for (Run& run : campaign.runs) {
        const auto found = flags->find(run.id);
        if (found == flags->end()) continue;
        QStringList masked;
        samples += sensors::maskFlaggedSamples(run, found->second, &masked);
        for (const QString& channel : masked)
            if (!channels.contains(channel)) channels << channel;
    }
    endProgressLine();
    std::fprintf(stderr,
                 "flags: %zu samples of %lld channel%s left out (--keep-flagged to use them)\n",
                 samples, static_cast<long long>(channels.size()), channels.size() == 1 ? "" : "s");
}

}  // namespace driftlab::cli
