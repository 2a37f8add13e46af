#pragma once
// The acceptance of a positioning run as JSON: the shape of
// `iso230-2 --json`'s "acceptance" object (docs/cli.md), also kept with a report.

#include <QJsonObject>
#include <QStringList>

#include "core/iso/PositioningAcceptance.h"

namespace driftlab::iso {

QJsonObject acceptanceJson(const PositioningAcceptance& acceptance);

/// The same as lines of text: environment, normalisation, budget, verdicts.
QStringList acceptanceText(const PositioningAcceptance& acceptance);

}  // namespace driftlab::iso
