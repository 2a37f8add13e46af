#pragma once
// A campaign of the simulated rig (driftlab-cli simulate), read back once per
// test binary: for tests of the library services that take a Campaign.
#include <gtest/gtest.h>

#include <map>

#include "core/bundle/BundleReader.h"
#include "tests/support/CliRunner.h"

namespace driftlab::test {

/// simulatedCampaign(runs, seed) as read by bundle::readBundle.
inline const Campaign& readSimulatedCampaign(const QString& runs, int seed) {
    static std::map<QString, Campaign> read;
    const QString key = runs + QLatin1Char('-') + QString::number(seed);
    auto found = read.find(key);
    if (found != read.end()) return found->second;
    const bundle::BundleReadResult r = bundle::readBundle(simulatedCampaign(runs, seed));
    EXPECT_TRUE(r.ok()) << qPrintable(r.error ? r.error->toString() : QString());
    return read.emplace(key, r.ok() ? *r.campaign : Campaign{}).first->second;
}

}  // namespace driftlab::test
