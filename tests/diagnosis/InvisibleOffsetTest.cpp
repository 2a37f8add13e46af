// Sensor effects on the channels off the screw (room, air, structure).
// Offsets: the air and structure sensors are read through their rise from the
// run's start (refraction and frame growth follow rises), so an offset there
// cancels exactly: it can be neither found nor harmful, and no candidate
// pretends to. The room sensor is different: the screw starts at the room
// temperature it soaked in, so its offset shows against every screw sensor,
// and the diagnosis has a candidate for it.
// Lags: the base model reads neither the air nor the structure sensor, so a
// lag there changes nothing until refraction or frame growth is present, and
// then they are found on top of it, in the second step. (A late room sensor
// is visible, in the screw's temperatures, and a candidate in the first step:
// the rig suite hides one.)
#include <gtest/gtest.h>

#include <cmath>

#include "core/diagnosis/Diagnosis.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/ModelScore.h"
#include "core/rig/CampaignSimulator.h"
#include "tests/diagnosis/SuiteStates.h"

using namespace driftlab;

namespace {

rig::RigSpec threeStates() {
    rig::RigSpec spec;
    spec.seed = 5;
    spec.runs = test::suiteStates();
    return spec;
}

/// The base model fitted on the training runs, its RMS on the held-out run.
double heldOutRms_um(const Campaign& campaign) {
    QStringList train, test;
    diagnosis::splitRuns(campaign, &train, &test);
    const auto trainData = models::buildDataset(campaign, train);
    const auto testData = models::buildDataset(campaign, test);
    EXPECT_TRUE(trainData.ok() && testData.ok());
    models::HeatTransferModel base;
    const auto fit = base.fit(trainData.runs);
    EXPECT_TRUE(fit.success) << qPrintable(fit.message);
    return models::scoreModel(base, testData.runs).rms_um;
}

/// The campaign of `spec` with the effects "ID=VALUE" added.
Campaign withEffects(rig::RigSpec spec, const QStringList& assignments) {
    for (const QString& assignment : assignments) {
        QString error;
        EXPECT_TRUE(rig::applyEffect(spec.effects, assignment, &error)) << qPrintable(error);
    }
    return rig::simulateCampaign(spec);
}

Campaign withOffset(const rig::RigSpec& spec, const QString& channel, double offset_K) {
    return withEffects(spec, {QStringLiteral("sensor_offset:%1=%2").arg(channel).arg(offset_K)});
}

const std::vector<double>& column(const Campaign& c, const QString& run, const QString& id) {
    const driftlab::Run& r = *c.findRun(run);
    return r.samples.values[std::size_t(r.samples.columnIndex(id))];
}

}  // namespace

TEST(InvisibleOffsets, anOffsetOnAirOrStructureCancelsInTheirRises) {
    const rig::RigSpec clean = threeStates();
    const Campaign reference = rig::simulateCampaign(clean);
    const double reference_um = heldOutRms_um(reference);
    for (const QString& channel : {clean.names.air, clean.names.structure}) {
        SCOPED_TRACE(channel.toStdString());
        const Campaign offset = withOffset(clean, channel, 0.5);
        // The logged channel reads 0.5 K high; every other column is the same.
        const auto& shifted = column(offset, QStringLiteral("S1"), channel);
        const auto& original = column(reference, QStringLiteral("S1"), channel);
        for (std::size_t i = 0; i < shifted.size(); i += 97) {
            if (!std::isnan(original[i])) {
                EXPECT_NEAR(shifted[i] - original[i], 0.5, 1e-9);
            }
        }
        EXPECT_EQ(column(offset, QStringLiteral("S1"), clean.names.nut),
                  column(reference, QStringLiteral("S1"), clean.names.nut));
        // The screw model's held-out prediction does not move.
        EXPECT_NEAR(heldOutRms_um(offset), reference_um, 1e-6 * reference_um);
    }
}

TEST(InvisibleOffsets, anOffsetOnTheRoomSensorIsNotInvisibleAndIsNamed) {
    // The screw starts at the room temperature: a room sensor 0.5 K high makes
    // every screw sensor look 0.5 K low, and the base fit bends to follow.
    const rig::RigSpec clean = threeStates();
    const Campaign offset = withOffset(clean, clean.names.ambient, 0.5);
    EXPECT_GT(heldOutRms_um(offset), 1.5 * heldOutRms_um(rig::simulateCampaign(clean)));
    const diagnosis::DiagnosisResult result = diagnosis::diagnose(offset);
    ASSERT_TRUE(result.ok()) << qPrintable(result.error);
    const QString cause = QStringLiteral("sensor_offset:") + clean.names.ambient;
    EXPECT_EQ(result.verdict, cause) << qPrintable(result.verdict_evidence);
    const diagnosis::Finding* f = diagnosis::adoptedFinding(result, cause);
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->parameters.at(0).second.value, 0.5, 0.1);
    EXPECT_EQ(f->gain.quantity, QStringLiteral("positioning"));
    // The evidence gives the gain's quantity once, then the screw temperatures.
    EXPECT_EQ(f->evidence.count(QStringLiteral("positioning residual")), 1)
        << qPrintable(f->evidence);
    EXPECT_TRUE(f->evidence.contains(QStringLiteral("the screw-temperature residual from ")));
}

TEST(InvisibleLags, aLagOnAirOrStructureLeavesTheBaseModelUnchanged) {
    const rig::RigSpec clean = threeStates();
    const double reference_um = heldOutRms_um(rig::simulateCampaign(clean));
    const Campaign lagged =
        withEffects(clean, {QStringLiteral("sensor_lag:%1=1200").arg(clean.names.air),
                            QStringLiteral("sensor_lag:%1=1800").arg(clean.names.structure)});
    EXPECT_NEAR(heldOutRms_um(lagged), reference_um, 1e-6 * reference_um);
}

TEST(InvisibleLags, aLateStructureSensorIsFoundOnTopOfFrameGrowth) {
    // The frame grows with the true structure temperature, which the sensor
    // shows an hour late: the effect leads the reading. frame_growth alone
    // (the frame behind its sensor) leaves a third; undoing the sensor's lag
    // on top of it takes most of the rest.
    const rig::RigSpec clean = threeStates();
    const Campaign lagged =
        withEffects(clean, {QStringLiteral("frame_growth=-6"),
                            QStringLiteral("sensor_lag:%1=3600").arg(clean.names.structure)});
    const diagnosis::DiagnosisResult result = diagnosis::diagnose(lagged);
    ASSERT_TRUE(result.ok()) << qPrintable(result.error);
    const QString late = QStringLiteral("sensor_lag:") + clean.names.structure;
    EXPECT_EQ(result.causes, QStringList({QStringLiteral("frame_growth"), late}))
        << qPrintable(result.verdict_evidence);
    const diagnosis::Finding* f = diagnosis::adoptedFinding(result, late);
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->parameters.at(0).second.value, 3600, 0.2 * 3600);
    EXPECT_EQ(f->step, 2);
}
