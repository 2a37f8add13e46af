#pragma once
// --spec FILE of the commands that accept an axis (iso230-2, report): the
// acceptance specification of docs/acceptance.md, else the campaign's own.

#include <QCommandLineParser>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/iso/AcceptanceSpecification.h"

namespace driftlab::cli {

/// --spec FILE.
QCommandLineOption acceptanceSpecOption();

/// --spec's file, else the campaign's `acceptance` object, else nullopt.
/// Throws CliError naming the key at fault when either is malformed.
std::optional<iso::AcceptanceSpecification> acceptanceSpecification(
    const QCommandLineParser& parser, const Campaign& campaign);

}  // namespace driftlab::cli
