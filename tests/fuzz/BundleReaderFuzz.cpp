// libFuzzer target: a whole bundle through readBundle. campaign.json is the
// valid example campaign (read once from the source tree); the input holds the
// CSV files, split at NUL bytes: samples.csv [\0 positioning.csv [\0 motion.csv]].
// A missing part is a missing file. Errors come back as BundleError; anything
// else (crash, leak, UB) is a bug.
#include <QFile>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "core/bundle/BundleReader.h"
#include "tests/fuzz/MemoryBundleSource.h"

namespace {

QByteArray campaignJson;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    QFile file(QStringLiteral(DRIFTLAB_SOURCE_DIR
                              "/resources/examples/x-axis-moving-state/campaign.json"));
    if (!file.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "cannot read %s\n", qPrintable(file.fileName()));
        std::exit(1);
    }
    campaignJson = file.readAll();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray input(reinterpret_cast<const char*>(data), qsizetype(size));
    const QList<QByteArray> parts = input.split('\0');
    static const QString names[] = {QStringLiteral("samples.csv"),
                                    QStringLiteral("positioning.csv"),
                                    QStringLiteral("motion.csv")};
    driftlab::MemoryBundleSource source;
    source.add(QStringLiteral("campaign.json"), campaignJson);
    for (qsizetype i = 0; i < parts.size() && i < 3; ++i) source.add(names[i], parts[i]);

    driftlab::bundle::BundleReadOptions options;
    options.progress = [](double fraction) {
        if (!(fraction >= 0 && fraction <= 1)) std::abort();
        return true;
    };
    const driftlab::bundle::BundleReadResult result = driftlab::bundle::readBundle(source, options);
    if (result.ok() == result.error.has_value()) std::abort();  // exactly one of them
    return 0;
}
