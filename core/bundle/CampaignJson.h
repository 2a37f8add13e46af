#pragma once
// campaign.json <-> Campaign (metadata only; the CSV files carry the data).

#include <QByteArray>
#include <QJsonObject>

#include "core/domain/Campaign.h"

namespace driftlab {

/// Parses campaign.json; throws BundleException naming the key path on bad input.
/// Runs are created without data.
Campaign campaignFromJson(const QByteArray& json, const QString& fileName);
/// The campaign.json object of a campaign (its runs without data).
QJsonObject campaignToJson(const Campaign& campaign);

}  // namespace driftlab
