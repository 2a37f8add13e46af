#pragma once
// campaign.json <-> Campaign (metadata only; the CSV files carry the data).

#include <QByteArray>
#include <QJsonObject>
#include <QStringList>

#include "core/domain/Campaign.h"

namespace driftlab::bundle {

/// Parses campaign.json; throws BundleException naming the key path on bad input.
/// Runs are created without data. Keys the format does not know are kept in
/// the `extra` of their object; one that misspells a key whose absence would
/// change a result (screw.alpha_perK) is refused, the others are named in
/// `warnings` (when given), except at the top level, where only a misspelling
/// is: the other keys there are other tools' data.
Campaign campaignFromJson(const QByteArray& json, const QString& fileName,
                          QStringList* warnings = nullptr);
/// The campaign.json object of a campaign (its runs without data).
QJsonObject campaignToJson(const Campaign& campaign);

}  // namespace driftlab::bundle
