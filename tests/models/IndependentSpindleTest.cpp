// `auto` on spindle campaigns DriftLab did not write (issue 10): another
// thermal network, sixteen thermometers (none on the shaft or the column
// core), thermometers logged every 10 s and probes every 5 s
// (tests/independent_sim/spindle_campaign.py). Fitted on three speed
// programmes, scored on three others, against plain least squares on all
// sixteen rises and on the best sensor pair. The campaigns also check the
// reader on a logger that writes two devices' rates into one file.
#include <gtest/gtest.h>

#include <QDir>

#include "core/bundle/BundleReader.h"
#include "tests/models/LeastSquaresBaselines.h"

namespace driftlab::models {
namespace {

TEST(IndependentSpindle, autoAgainstLeastSquaresOnAllSixteenRisesAndTheBestPair) {
    const QDir suite(QStringLiteral(DRIFTLAB_INDEPENDENT_SPINDLE));
    const QStringList campaigns = suite.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    ASSERT_FALSE(campaigns.isEmpty()) << "no campaign in " << qPrintable(suite.path());
    test::printAutoAgainstBaselinesHeader();
    test::AutoAgainstBaselinesTally tally;
    for (const QString& name : campaigns) {
        const BundleReadResult read = readBundle(suite.filePath(name));
        ASSERT_TRUE(read.ok()) << qPrintable(read.error->toString());
        const Campaign& c = *read.campaign;
        for (const Channel& probe : c.channels) {
            if (probe.quantity != Quantity::Displacement) continue;
            SCOPED_TRACE(qPrintable(name + QLatin1Char(' ') + probe.id));
            const auto train = test::driftDataset(c, {"P1", "P2", "P3"}, probe.id);
            const auto test = test::driftDataset(c, {"P4", "P5", "P6"}, probe.id);
            ASSERT_FALSE(train.empty() || test.empty());
            ASSERT_EQ(train.front().temperatures.size(), 16u);
            const test::AutoAgainstBaselines a =
                test::autoAgainstBaselines(train, test, name + QLatin1Char(' ') + probe.id);
            ASSERT_TRUE(a.score.ok());
            tally.add(a);
            // Sixteen sensors around the heat paths follow the unsensed shaft
            // and column core nearly as a lag would: every model ends near the
            // probes' noise (0.15 µm), where cross-validation over three
            // training runs cannot rank them (each fold fits on two). `auto`
            // may lose there, never by more than that noise …
            EXPECT_LT(a.score.rms_um, a.baselines.better_um() + 0.15);
            // … and it takes out the tens of µm of z drift as well as the baselines do.
            if (probe.role == ChannelRole::DriftZ) {
                EXPECT_GT(a.score.reduction, 0.98);
            }
        }
    }
    // Not asserted: beating both on every probe (see docs/models.md).
    tally.print();
}

}  // namespace
}  // namespace driftlab::models
