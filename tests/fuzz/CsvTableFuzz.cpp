// libFuzzer target: the input is a samples.csv read through CsvTable; every
// field of every record goes through each typed accessor. A BundleException is
// the expected answer to bad input; anything else (crash, leak, UB) is a bug.
#include <QBuffer>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "core/bundle/CsvTable.h"

using driftlab::bundle::BundleException;
using driftlab::bundle::CsvTable;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto buffer = std::make_unique<QBuffer>();
    buffer->setData(reinterpret_cast<const char*>(data), qsizetype(size));
    if (!buffer->open(QIODevice::ReadOnly)) return 0;
    try {
        driftlab::bundle::CsvTable csv(std::move(buffer), QStringLiteral("samples.csv"));
        (void)csv.europeanFormat();
        (void)csv.column(QStringLiteral("run"));
        const int columns = int(csv.header().size());
        while (csv.next()) {
            (void)csv.line();
            (void)csv.progress();
            for (int c = 0; c < columns; ++c) {
                (void)csv.field(c);
                (void)csv.text(c);
                try {
                    (void)csv.number(c);
                } catch (const driftlab::bundle::BundleException&) {
                }
                try {
                    (void)csv.numberOrMissing(c);
                } catch (const driftlab::bundle::BundleException&) {
                }
                try {
                    (void)csv.integer(c);
                } catch (const driftlab::bundle::BundleException&) {
                }
            }
        }
    } catch (const driftlab::bundle::BundleException&) {
    }
    return 0;
}
