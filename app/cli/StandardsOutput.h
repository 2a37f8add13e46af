#pragma once
// What `iso230-2 --standard NAME|all` prints: one standard's values, or every
// standard side by side, as text or JSON (docs/cli.md, docs/standards.md).

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/iso/PositioningStandards.h"

namespace driftlab::cli {

/// One standard's JSON: id, standard, coverage_factor, min_approaches,
/// definitions, values (key → µm, null when not determined), skipped, warnings.
QJsonObject standardEvaluationJson(const iso::StandardEvaluation& evaluation);
/// `--standard all --json` without its source: unit, standards (as above, in
/// comparison order), not_evaluated (id, standard, why) and warnings.
QJsonObject standardsComparisonJson(const iso::StandardsComparison& comparison);

void printStandardEvaluation(const iso::StandardEvaluation& evaluation, const QString& source);
/// A row per parameter, a column per standard; "n/a" = not determined, "-" =
/// not defined by that standard; then each standard's coverage and what is left out.
void printStandardsComparison(const iso::StandardsComparison& comparison, const QString& source);

/// What --standard asks for: neither set for the default ISO 230-2
/// evaluation (also for an ISO 230-2 id, which only sets the edition), one
/// other standard, or every standard side by side (`all`).
struct StandardChoice {
    bool all = false;
    std::optional<iso::PositioningStandard> standard;
};

/// Reads --standard; for an ISO 230-2 id sets `settings.edition`. Throws
/// CliError (exit 2) for a left-out or unknown name, for --edition naming
/// another edition, and for --edition or --coverage-factor with a standard
/// that fixes its own.
StandardChoice chooseStandard(const QCommandLineParser& parser, const QCommandLineOption& option,
                              const QCommandLineOption& edition, const QCommandLineOption& coverage,
                              iso::Settings& settings);

/// Evaluates `readings` by the chosen standard (or all), prints text or JSON
/// with `source`, and returns the exit code; throws CliError on a refusal.
int evaluateByStandard(const StandardChoice& choice, const std::vector<iso::Reading>& readings,
                       const iso::Settings& settings, const QString& source, bool asJson);

}  // namespace driftlab::cli
