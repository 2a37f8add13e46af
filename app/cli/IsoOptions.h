#pragma once
// The options of the commands that evaluate ISO 230-2 (iso230-2, iso230-3,
// history, report): the edition, the coverage factor and --spec, the
// acceptance specification of docs/acceptance.md.

#include <QCommandLineParser>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/Iso230_2.h"

namespace driftlab::cli {

/// --edition YEAR (2014, 2006, 1997).
QCommandLineOption isoEditionOption();
/// --coverage-factor K.
QCommandLineOption isoCoverageOption();
/// The settings those two options give; exit 2 naming the option when one is wrong.
iso::Settings isoSettings(const QCommandLineParser& parser);

/// --spec FILE.
QCommandLineOption acceptanceSpecOption();

/// --spec's file, else the campaign's `acceptance` object, else nullopt.
/// Throws CliError naming the key at fault when either is malformed.
std::optional<iso::AcceptanceSpecification> acceptanceSpecification(
    const QCommandLineParser& parser, const Campaign& campaign);

}  // namespace driftlab::cli
