// libFuzzer target: the input is an active compensation table handed to
// `compensate --active-table`, read as DriftLab CSV and as each controller's
// own file. An error message is the expected answer to bad input; anything
// else (crash, leak, UB) is a bug.
#include <QByteArray>
#include <QString>
#include <cstddef>
#include <cstdint>

#include "core/compensation/ActiveTableRead.h"

using driftlab::compensation::readActiveTable;
using driftlab::compensation::ValueSign;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray text(reinterpret_cast<const char*>(data), qsizetype(size));
    for (const char* format :
         {"", "linuxcnc", "linuxcnc-type1", "sinumerik", "heidenhain", "fanuc"})
        for (ValueSign sign : {ValueSign::Correction, ValueSign::Error}) {
            const auto read =
                readActiveTable(text, QString::fromLatin1(format), sign, QStringLiteral("active"));
            if (read.ok()) (void)read.table.maxAbsCorrectionUm();
        }
    return 0;
}
