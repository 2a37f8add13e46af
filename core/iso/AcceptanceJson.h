#pragma once
// The acceptance of a positioning run as JSON: the shape of
// `iso230-2 --json`'s "acceptance" object (docs/cli.md), also kept with a report.

#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>

#include "core/iso/PositioningAcceptance.h"

namespace driftlab::iso {

QJsonObject acceptanceJson(const PositioningAcceptance& acceptance);

/// Decisions as the JSON array and the text table both outputs use.
QJsonArray decisionsJson(const std::vector<Decision>& decisions);
QStringList decisionsText(const std::vector<Decision>& decisions);

/// The decision rule in one sentence.
QString decisionRuleText();

/// The same as lines of text: environment, normalisation, budget, verdicts.
QStringList acceptanceText(const PositioningAcceptance& acceptance);

}  // namespace driftlab::iso
