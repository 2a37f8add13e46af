// `auto` on real spindle drift (tests/data/fl-thermal: FL_THERMAL's first
// 32 h, MIT licence), as a test engineer would use it: trained on the three
// lower constant speeds, scored on 5000 rpm, which the fit never saw. On each
// of the five probes it must beat both least-squares fits a user would make
// without DriftLab (every rise; the best pair of sensors), and never make the
// drift worse than no compensation; its prediction interval, at a speed
// beyond the training speeds, must hold what it claims.

#include <gtest/gtest.h>

#include <QJsonObject>

#include "core/bundle/BundleReader.h"
#include "core/models/AutoModel.h"
#include "core/models/ModelValidation.h"
#include "tests/models/ValidationRecord.h"
#include "tests/support/LeastSquaresBaselines.h"

using namespace driftlab;

namespace {

const Campaign& flThermal() {
    static const Campaign campaign = [] {
        const bundle::BundleReadResult read =
            bundle::readBundle(QStringLiteral(DRIFTLAB_FL_THERMAL_BUNDLE));
        EXPECT_TRUE(read.ok()) << "written by the ctest fixture fl_thermal_bundle_generate: "
                               << (read.ok() ? "" : qPrintable(read.error->toString()));
        return read.ok() ? *read.campaign : Campaign{};
    }();
    return campaign;
}

class RealSpindleDrift : public testing::TestWithParam<const char*> {};

TEST_P(RealSpindleDrift, autoBeatsBothLeastSquaresFitsOnASpeedItWasNotTrainedOn) {
    const QString probe = QString::fromLatin1(GetParam());
    const auto train = test::driftDataset(
        flThermal(), {QStringLiteral("R1250"), QStringLiteral("R2500"), QStringLiteral("R3750")},
        probe);
    const auto heldOut = test::driftDataset(flThermal(), {QStringLiteral("R5000")}, probe);
    ASSERT_FALSE(train.empty());
    ASSERT_FALSE(heldOut.empty());
    const models::ValidatedFit fit = models::fitValidated(QStringLiteral("auto"), train);
    ASSERT_TRUE(fit.fit.success) << qPrintable(fit.fit.message);
    const models::Score score = models::scoreModel(*fit.model, heldOut);
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    const test::LeastSquaresBaselines baselines = test::leastSquaresBaselines(train, heldOut);
    const QString chose = fit.fit.notes.isEmpty() ? QString() : fit.fit.notes.front();
    EXPECT_LT(score.rms_um, baselines.all_rises.rms_um)
        << qPrintable(probe) << ": auto " << score.rms_um << " µm, least squares on every rise "
        << baselines.all_rises.rms_um << " µm; " << qPrintable(chose);
    EXPECT_LT(score.rms_um, baselines.best_pair.rms_um)
        << qPrintable(probe) << ": auto " << score.rms_um << " µm, best pair "
        << qPrintable(baselines.best_pair_sensors) << " " << baselines.best_pair.rms_um << " µm; "
        << qPrintable(chose);
    EXPECT_GT(score.reduction, 0) << qPrintable(probe) << ": auto " << score.rms_um
                                  << " µm against " << score.uncompensated_rms_um
                                  << " µm uncompensated; " << qPrintable(chose);
    // Every prediction says how sure it is.
    EXPECT_TRUE(fit.validation.interval.known()) << qPrintable(probe);
    // 5000 rpm lies beyond the training speeds: the interval there comes from
    // the folds that extrapolated, and holds what it claims.
    EXPECT_TRUE(models::beyondTraining(train, heldOut.front())) << qPrintable(probe);
    EXPECT_TRUE(fit.validation.interval.knownBeyond()) << qPrintable(probe);
    const models::Coverage coverage =
        models::coverageOf(*fit.model, fit.validation.interval, heldOut, train);
    EXPECT_FALSE(coverage.farBelowClaim()) << qPrintable(probe) << ": " << coverage.share;
    test::writeValidationRecord(
        QStringLiteral("fl-thermal"), probe,
        {{QStringLiteral("probe"), probe},
         {QStringLiteral("uncompensated_um"), score.uncompensated_rms_um},
         {QStringLiteral("all_rises_um"), baselines.all_rises.rms_um},
         {QStringLiteral("best_pair_um"), baselines.best_pair.rms_um},
         {QStringLiteral("best_pair"), baselines.best_pair_sensors},
         {QStringLiteral("auto_um"), score.rms_um},
         {QStringLiteral("chosen"), static_cast<const models::AutoModel&>(*fit.model).chosen()},
         {QStringLiteral("interval_um"), fit.validation.interval.half_width_um},
         {QStringLiteral("beyond_interval_um"), fit.validation.interval.beyond_half_width_um},
         {QStringLiteral("coverage"), coverage.share}});
}

INSTANTIATE_TEST_SUITE_P(FlThermal, RealSpindleDrift,
                         testing::Values("ch1_um", "ch2_um", "ch3_um", "ch4_um", "ch5_um"));

}  // namespace
