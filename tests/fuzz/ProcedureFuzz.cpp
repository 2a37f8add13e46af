// libFuzzer target: the input is a procedure file (JSON) through
// parseProcedureJson, the reader under loadProcedureFile. A refusal (nullopt
// with a message) is the expected answer to bad input; nothing may throw. An
// accepted procedure is written back with toJson and must read again to the
// same JSON: the UI saves procedures that way, and the engine reruns them.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/procedures/Procedure.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    namespace procedures = driftlab::procedures;
    const QByteArray json(reinterpret_cast<const char*>(data), qsizetype(size));
    QString error;
    const auto procedure = procedures::parseProcedureJson(json, &error);
    if (!procedure) {
        if (error.isEmpty()) std::abort();  // a refusal must say why
        return 0;
    }
    if (!error.isEmpty()) std::abort();
    const QJsonObject written = procedures::toJson(*procedure);
    const auto again = procedures::parseProcedure(written, &error);
    if (!again || procedures::toJson(*again) != written) std::abort();
    return 0;
}
