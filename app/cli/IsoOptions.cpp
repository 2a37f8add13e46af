#include "app/cli/IsoOptions.h"

#include "app/cli/CliCommon.h"

namespace driftlab::cli {

QCommandLineOption isoEditionOption() {
    return {QStringLiteral("edition"),
            QStringLiteral("ISO 230-2 edition named in the output: 2014 (default), 2006 or 1997."),
            QStringLiteral("YEAR"), QStringLiteral("2014")};
}

QCommandLineOption isoCoverageOption() {
    return {
        QStringLiteral("coverage-factor"),
        QStringLiteral("k of the expanded quantities (default 2: R↑_i = 4s↑_i, A from x̄ ± 2s)."),
        QStringLiteral("K"), QStringLiteral("2")};
}

iso::Settings isoSettings(const QCommandLineParser& parser) {
    iso::Settings settings;
    const QString edition = parser.value(QStringLiteral("edition"));
    const auto year = iso::editionFromString(edition);
    if (!year)
        throw CliError(QStringLiteral("--edition: '%1' is not 2014, 2006 or 1997").arg(edition), 2);
    settings.edition = *year;
    settings.coverage_factor = positiveNumberOption(parser, isoCoverageOption());
    return settings;
}

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
