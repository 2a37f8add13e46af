// The straight-line temperature compensation: a least-squares line worked by
// hand, and the Sinumerik and ISG parameter files it becomes.
#include <gtest/gtest.h>

#include "core/compensation/TemperatureCompensationLine.h"

namespace driftlab::compensation {
namespace {

TEST(TemperatureCompensationLine, anExactLineIsRecoveredAtAnyReference) {
    // error = 3 µm + 12 µm/m · (x − 100 mm)
    const std::vector<double> x{0, 200, 400, 700};
    std::vector<double> e;
    for (double xi : x) e.push_back(3 + 12 * (xi - 100) / 1000);
    const ErrorLine at100 = fitErrorLine(x, e, 100);
    ASSERT_TRUE(at100.ok()) << at100.error.toStdString();
    EXPECT_NEAR(at100.offset_um, 3, 1e-12);
    EXPECT_NEAR(at100.slope_um_per_m, 12, 1e-12);
    EXPECT_NEAR(at100.residual_rms_um, 0, 1e-12);
    const ErrorLine at0 = fitErrorLine(x, e, 0);
    EXPECT_NEAR(at0.offset_um, 1.8, 1e-12);  // 3 − 12 µm/m · 0.1 m
    EXPECT_NEAR(at0.errorAt_um(700), 10.2, 1e-12);
}

TEST(TemperatureCompensationLine, whatTheLineLeavesIsReported) {
    // (0, 0), (500, 0), (1000, 6): x̄ = 500, ē = 2, Sxx = 500000,
    // Sxe = (−500)(−2) + 0 + 500·4 = 3000 → slope 0.006 µm/mm = 6 µm/m,
    // line at 0: 2 − 3 = −1; residuals 1, −2, 1 → RMS √2, peak 2.
    const ErrorLine line = fitErrorLine({0, 500, 1000}, {0, 0, 6}, 0);
    ASSERT_TRUE(line.ok());
    EXPECT_NEAR(line.slope_um_per_m, 6, 1e-12);
    EXPECT_NEAR(line.offset_um, -1, 1e-12);
    EXPECT_NEAR(line.residual_rms_um, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(line.residual_peak_um, 2, 1e-12);
}

TEST(TemperatureCompensationLine, pointsThatGiveNoLineAreRefused) {
    EXPECT_FALSE(fitErrorLine({100}, {1}, 0).ok());
    EXPECT_TRUE(fitErrorLine({100, 100}, {1, 2}, 0).error.contains(QStringLiteral("100 mm")));
    EXPECT_TRUE(fitErrorLine({0, NAN}, {1, 2}, 0).error.contains(QStringLiteral("point 1")));
}

TEST(TemperatureCompensationLine, sinumerikSettingDataHoldTheErrorInMillimetres) {
    const ErrorLine line = fitErrorLine({0, 200, 400, 700}, {1.8, 4.2, 6.6, 10.2}, 0);
    const ExportResult out = exportSinumerikTemperatureLine(line, QStringLiteral("X1"));
    ASSERT_TRUE(out.ok()) << out.error.toStdString();
    EXPECT_TRUE(out.text.startsWith("%_N_DRIFTLAB_TEMP_COMP_SPF\n;$PATH=/_N_SPF_DIR\n"));
    EXPECT_TRUE(out.text.contains("\n$SA_TEMP_COMP_ABS_VALUE[X1]=0.0018\n"));
    EXPECT_TRUE(out.text.contains("\n$SA_TEMP_COMP_SLOPE[X1]=0.00001200\n"));
    EXPECT_TRUE(out.text.contains("\n$SA_TEMP_COMP_REF_POSITION[X1]=0.0000\nM17\n"));
    EXPECT_TRUE(out.text.contains("MD32750 $MA_TEMP_COMP_TYPE[X1]=3"));
    EXPECT_FALSE(exportSinumerikTemperatureLine(line, QStringLiteral("X 1")).ok());
}

TEST(TemperatureCompensationLine, isgParametersHoldTheCorrectionInTenthsOfMicrometres) {
    const ErrorLine line = fitErrorLine({0, 200, 400, 700}, {1.8, 4.2, 6.6, 10.2}, 0);
    const ExportResult out = exportIsgTemperatureLine(line);
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(out.text,
              "# DriftLab straight-line temperature compensation\n"
              "lr_param.temp_comp                  1\n"
              "lr_param.temp_comp_position_0       0\n"
              "lr_param.temp_comp_offset_0         -18\n"
              "lr_param.temp_comp_coefficient      -12\n");
    EXPECT_TRUE(out.warnings.isEmpty());
}

}  // namespace
}  // namespace driftlab::compensation
