// The correction of a reading taken with the interferometer's compensation off.
#include <gtest/gtest.h>

#include "core/interferometer/EnvironmentCorrection.h"

using namespace driftlab;

TEST(EnvironmentCorrection, compensatedReadingIsLeftAloneAndSaysSo) {
    const interferometer::EnvironmentCorrection c = interferometer::noCorrection();
    EXPECT_FALSE(c.applied);
    EXPECT_EQ(c.correctedLength_mm(500.0), 500.0);
    EXPECT_EQ(c.correctedDeviation_um(500.0, 3.5), 3.5);
    EXPECT_EQ(c.description, QStringLiteral("none: the interferometer compensated itself"));
}

// The physics, independently of the formula in the code: fringes N counted
// over a true length L in air of index n are N = 2·L·n/λ; a reading with an
// assumed n0 is N·λ/(2·n0). Correcting it must give L back.
TEST(EnvironmentCorrection, recoversTheTrueLengthFromTheFringeCount) {
    const interferometer::AirState air{23.4, 98'700.0, 35.0};
    const double n = interferometer::edlenRefractiveIndex(air);
    const double lambda_mm = interferometer::kHeNeVacuumWavelength_nm * 1e-6;
    const double trueLength_mm = 734.125;
    const double fringes = 2.0 * trueLength_mm * n / lambda_mm;
    for (double n0 : {1.0, interferometer::standardAirIndex()}) {
        const double reading_mm = fringes * lambda_mm / (2.0 * n0);
        const interferometer::EnvironmentCorrection c = interferometer::edlenCorrection(air, n0);
        EXPECT_NEAR(c.correctedLength_mm(reading_mm), trueLength_mm, 1e-9) << n0;
    }
}

// Sign: air 1 K warmer than the assumed standard air is thinner (n < n0), the
// wavelength longer, the reading short: the corrected length is longer by
// ≈ +0.93 ppm. A vacuum wavelength in air is off by ≈ −271 ppm.
TEST(EnvironmentCorrection, signAndSizeMatchTheRulesOfThumb) {
    const interferometer::EnvironmentCorrection warm = interferometer::edlenCorrection(
        interferometer::AirState{21.0, 101'325.0, 50.0}, interferometer::standardAirIndex());
    EXPECT_TRUE(warm.applied);
    EXPECT_NEAR(warm.correction_ppm, 0.93, 0.03);
    EXPECT_GT(warm.correctedLength_mm(1000.0), 1000.0);

    const interferometer::EnvironmentCorrection standard = interferometer::edlenCorrection(
        interferometer::AirState{}, interferometer::standardAirIndex());
    EXPECT_NEAR(standard.correction_ppm, 0.0, 1e-9);

    const interferometer::EnvironmentCorrection vacuum =
        interferometer::edlenCorrection(interferometer::AirState{}, 1.0);
    EXPECT_NEAR(vacuum.correction_ppm, -271.4, 0.5);
}

TEST(EnvironmentCorrection, deviationTakesTheLengthCorrectionOfItsPosition) {
    interferometer::EnvironmentCorrection c;
    c.applied = true;
    c.factor = 1.0 - 2e-6;  // −2 ppm
    // 500 mm read, 10 µm deviation: the actual is 1 µm shorter, the target exact.
    EXPECT_NEAR(c.correctedDeviation_um(500.0, 10.0), 9.0, 1e-9);
    EXPECT_NEAR(c.correctedLength_mm(500.0), 499.999, 1e-12);
}

TEST(EnvironmentCorrection, descriptionSaysWhichCorrectionWithTheAir) {
    const interferometer::AirState air{20.3, 101'100.0, 45.0};
    const interferometer::EnvironmentCorrection c =
        interferometer::edlenCorrection(air, interferometer::standardAirIndex());
    const QString ppm = QString::number(c.correction_ppm, 'f', 2).replace(u'-', QChar(0x2212));
    EXPECT_EQ(c.description, QStringLiteral("Edlén, 20.3 °C, 101.1 kPa, 45 %RH: %1 ppm").arg(ppm));
    // Against standard air: 0.3 K warmer (+0.28 ppm), 225 Pa lower (+0.61 ppm),
    // 5 %RH drier (−0.04 ppm), by the rules of thumb above.
    EXPECT_NEAR(c.correction_ppm, 0.28 + 0.61 - 0.04, 0.03);
}

TEST(EnvironmentCorrection, refusesAirOutOfRange) {
    EXPECT_THROW(
        interferometer::edlenCorrection(interferometer::AirState{20.0, 1013.25, 50.0}, 1.0),
        std::invalid_argument);
    EXPECT_THROW(interferometer::edlenCorrection(interferometer::AirState{}, 1.5),
                 std::invalid_argument);
}
