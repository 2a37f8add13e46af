#include "app/cli/AcceptanceOption.h"

#include "app/cli/ConsoleOutput.h"

namespace driftlab::cli {

QCommandLineOption acceptanceSpecOption() {
    return {QStringLiteral("spec"),
            QStringLiteral("Acceptance specification (driftlab.acceptance/1: tolerances, set-up "
                           "uncertainty, 20 °C): readings normalised to 20 °C, uncertainty "
                           "budget, PASS/FAIL/NOT PROVEN by ISO 14253-1. Default: the "
                           "campaign's own `acceptance` object, if any."),
            QStringLiteral("FILE")};
}

std::optional<iso::AcceptanceSpecification> acceptanceSpecification(
    const QCommandLineParser& parser, const Campaign& campaign) {
    const QString path = parser.value(QStringLiteral("spec"));
    QString error;
    const auto spec = path.isEmpty() ? iso::campaignAcceptance(campaign, &error)
                                     : iso::readAcceptanceSpecification(path, &error);
    if (!error.isEmpty()) throw CliError(error);
    return spec;
}

}  // namespace driftlab::cli
