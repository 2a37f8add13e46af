#pragma once
// Every bad-input class of the bundle format (issue 2): a defect applied to a
// copy of the example bundle, and where and why the reader must refuse it.
// The same table runs through readBundle (BundleValidationTest) and through
// the real driftlab-cli (CliTest).

#include <QString>
#include <functional>
#include <ostream>
#include <vector>

namespace driftlab::test {

/// A bundle with one defect and where and why the reader must say it is bad.
struct BadBundleCase {
    const char* name;
    std::function<void(const QString& bundleDir)> breakIt;
    const char* expectedLocation;  ///< e.g. "samples.csv:4:3"
    const char* expectedMessage;   ///< a part of the message
};
void PrintTo(const BadBundleCase& bad, std::ostream* os);
/// Every bad-input class of the bundle format (issue #2), applied to a copy of the example.
const std::vector<BadBundleCase>& badBundleCases();

}  // namespace driftlab::test
