// driftlab-cli live: the heat-transfer model fitted on S1 compensates S3 of
// a simulated campaign online; the correction it applies between cuts is
// scored on S3's measured thermal error, which the fit never saw.

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

const QString& twoStateBundle() {
    return simulatedCampaign(QStringLiteral("S1,S3"), 5);
}

QJsonObject live(const QStringList& more) {
    const CliResult r =
        runCli(QStringList{QStringLiteral("live"), twoStateBundle(), QStringLiteral("--run"),
                           QStringLiteral("S3"), QStringLiteral("--train"), QStringLiteral("S1"),
                           QStringLiteral("--json")} +
               more);
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out).object();
}

}  // namespace

TEST(LiveCli, correctionFromTheModelFittedOnS1RemovesMostOfS3sThermalError) {
    const QJsonObject out = live({});
    EXPECT_GT(out["readings"].toInt(), 100);
    EXPECT_GT(out["rms_before_um"].toDouble(), 10);  // S3 warms the screw by tens of µm
    // Held out, with the real delays of one update a minute: more than 80 % removed.
    EXPECT_GT(out["reduction"].toDouble(), 0.8);
    // One offset for the whole travel (an external offset) cannot follow a
    // growth that depends on position: better than nothing, worse than the table.
    EXPECT_LT(out["rms_after_um"].toDouble(), out["rms_after_offset_um"].toDouble());
    EXPECT_LT(out["rms_after_offset_um"].toDouble(), out["rms_before_um"].toDouble());
    EXPECT_NEAR(out["reduction"].toDouble(),
                1 - out["rms_after_um"].toDouble() / out["rms_before_um"].toDouble(), 1e-12);
}

TEST(LiveCli, updatesDueDuringACutWaitUntilItEndsAndChangeByAtMostTheLimit) {
    const QJsonObject out = live({QStringLiteral("--cutting"), QStringLiteral("0-1800,3000-3600"),
                                  QStringLiteral("--max-change-um"), QStringLiteral("2")});
    const QJsonArray updates = out["updates"].toArray();
    ASSERT_GT(updates.size(), 10);
    double previous_um = 0;
    bool waited = false;
    for (const QJsonValue& u : updates) {
        const double t = u["time_s"].toDouble();
        EXPECT_FALSE((t > 0 && t <= 1800) || (t > 3000 && t <= 3600)) << "applied mid-cut at " << t;
        EXPECT_LE(std::abs(u["offset_um"].toDouble() - previous_um), 2 + 1e-9) << "at " << t;
        previous_um = u["offset_um"].toDouble();
        waited |= u["due_s"].toDouble() < t - 1;
    }
    EXPECT_TRUE(waited);
    EXPECT_DOUBLE_EQ(updates.first()["due_s"].toDouble(), 60);
    EXPECT_GT(updates.first()["time_s"].toDouble(), 1800);
    // Held back at the start, the correction is worse than without cuts, still a gain.
    EXPECT_LT(out["reduction"].toDouble(), live({})["reduction"].toDouble());
    EXPECT_GT(out["reduction"].toDouble(), 0.2);
}

TEST(LiveCli, theReplayedRunCannotAlsoBeATrainingRun) {
    const CliResult r =
        runCli({QStringLiteral("live"), twoStateBundle(), QStringLiteral("--run"),
                QStringLiteral("S1"), QStringLiteral("--train"), QStringLiteral("S1")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("S1")) << r.err.constData();
    const CliResult bad =
        runCli({QStringLiteral("live"), twoStateBundle(), QStringLiteral("--run"),
                QStringLiteral("S3"), QStringLiteral("--train"), QStringLiteral("S1"),
                QStringLiteral("--cutting"), QStringLiteral("900-300")});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_TRUE(reason(bad.err).contains("900-300")) << bad.err.constData();
}
