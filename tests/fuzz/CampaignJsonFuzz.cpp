// libFuzzer target: the input is a campaign.json. A BundleException is the
// expected answer to bad input; a parsed campaign is written back to JSON and
// must read again (the writer keeps unknown keys, so the round trip is lossless).
#include <QJsonDocument>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "core/bundle/BundleError.h"
#include "core/bundle/CampaignJson.h"

using driftlab::bundle::BundleException;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray json(reinterpret_cast<const char*>(data), qsizetype(size));
    driftlab::Campaign campaign;
    try {
        campaign = driftlab::bundle::campaignFromJson(json, QStringLiteral("campaign.json"));
    } catch (const driftlab::bundle::BundleException&) {
        return 0;
    }
    const QByteArray written = QJsonDocument(driftlab::bundle::campaignToJson(campaign)).toJson();
    try {
        (void)driftlab::bundle::campaignFromJson(written, QStringLiteral("campaign.json"));
    } catch (const driftlab::bundle::BundleException&) {
        std::abort();  // a campaign we accepted must survive its own export
    }
    return 0;
}
