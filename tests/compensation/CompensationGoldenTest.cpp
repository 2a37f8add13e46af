// Every export format of the hand-checked table (CompensationTestData.h),
// compared byte for byte with tests/compensation/golden/. The expected values
// are worked out in the comments beside each file's test.

#include <gtest/gtest.h>

#include <QFile>
#include <cmath>

#include "core/compensation/CsvExport.h"
#include "core/compensation/FanucExport.h"
#include "core/compensation/HeidenhainExport.h"
#include "core/compensation/LinuxCncExport.h"
#include "core/compensation/SinumerikExport.h"
#include "tests/compensation/CompensationTestData.h"

namespace driftlab::compensation {
namespace {

using test::golden50mm;

QByteArray golden(const char* name) {
    QFile file(QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/compensation/golden/") +
               QLatin1String(name));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << name;
    return file.readAll();
}

void expectGolden(const ExportResult& exported, const char* name) {
    ASSERT_TRUE(exported.ok()) << qPrintable(exported.error);
    EXPECT_EQ(exported.text, golden(name)) << name << ":\n" << exported.text.constData();
}

CompensationTable unidirectional() {
    TableResult r = golden50mm(false);
    EXPECT_TRUE(r.ok()) << qPrintable(r.error);
    return r.table;
}

CompensationTable bidirectional() {
    TableResult r = golden50mm(true);
    EXPECT_TRUE(r.ok()) << qPrintable(r.error);
    return r.table;
}

TEST(CompensationGolden, tableIsMinusTheInterpolatedMeanDeviations) {
    const CompensationTable u = unidirectional();
    ASSERT_EQ(u.size(), 5u);
    const double mean[] = {-0.5, -2.0, -3.5, -0.5, 2.5};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_DOUBLE_EQ(u.position_mm[i], 50.0 * double(i));
        EXPECT_NEAR(u.meanCorrectionUm(i), mean[i], 1e-12) << i;
    }
    EXPECT_NEAR(u.mean_reversal_um, 3, 1e-12);
    const CompensationTable b = bidirectional();
    const double plus[] = {-3, -3.5, -4, -1.5, 1}, minus[] = {2, -0.5, -3, 0.5, 4};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(b.correction_plus_um[i], plus[i], 1e-12) << i;
        EXPECT_NEAR(b.correction_minus_um[i], minus[i], 1e-12) << i;
    }
    // The expanded uncertainty of each point from the cycles' scatter
    // (CompensationTestData.h).
    const double at0 = std::sqrt(2.0 / 5), at100 = std::sqrt(0.5), at200 = std::sqrt(1.0 / 5);
    const double uni[] = {at0, (at0 + at100) / 2, at100, (at100 + at200) / 2, at200};
    const double bi[] = {2 / std::sqrt(5.0), 2.5 / std::sqrt(5.0), 3 / std::sqrt(5.0),
                         2.5 / std::sqrt(5.0), 2 / std::sqrt(5.0)};
    ASSERT_EQ(u.uncertainty_um.size(), 5u);
    ASSERT_EQ(b.uncertainty_um.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(u.uncertainty_um[i], uni[i], 1e-12) << i;
        EXPECT_NEAR(b.uncertainty_um[i], bi[i], 1e-12) << i;
    }
}

// Unidirectional: LinuxCNC ignores BACKLASH with a COMP_FILE, so B̄ = 3 is
// folded in: trim+ = −x̄ − B̄/2, trim− = −x̄ + B̄/2; type 0 writes actual =
// nominal − trim. At 50 mm: trim+ = −2 − 1.5 = −3.5 µm → 50.0035,
// trim− = −2 + 1.5 = −0.5 µm → 50.0005.
TEST(CompensationGolden, linuxCncType0Unidirectional) {
    expectGolden(exportLinuxCnc(unidirectional(), LinuxCncType::Type0), "linuxcnc_type0.comp");
}

// Bidirectional type 1: the trims themselves, −x̄↑ and −x̄↓ in mm.
TEST(CompensationGolden, linuxCncType1Bidirectional) {
    expectGolden(exportLinuxCnc(bidirectional(), LinuxCncType::Type1),
                 "linuxcnc_type1_bidirectional.comp");
}

// Bidirectional type 0: actual± = nominal + x̄± (e.g. 0 mm: 0.0030, −0.0020).
TEST(CompensationGolden, linuxCncType0Bidirectional) {
    expectGolden(exportLinuxCnc(bidirectional(), LinuxCncType::Type0),
                 "linuxcnc_type0_bidirectional.comp");
}

// Fanuc, 1 µm detection unit, magnification 1, reference at 0 mm (number 0).
// Absolute corrections rounded half away from zero: −1, −2, −4, −1, 3;
// increments from number 1 on: −1, −2, 3, 4. 1851 = −B̄ = −3.
TEST(CompensationGolden, fanucParameterFile) {
    expectGolden(exportFanucParameters(unidirectional(), {}), "fanuc.prm");
}

TEST(CompensationGolden, fanucG10Programme) {
    expectGolden(exportFanucG10(unidirectional(), {}), "fanuc_g10.nc");
}

// Sinumerik holds +deviation (a positive value moves the axis negative):
// x̄ in mm, 0.0005, 0.0020, 0.0035, 0.0005, −0.0025.
TEST(CompensationGolden, sinumerikEec) {
    expectGolden(exportSinumerik(unidirectional(), {}), "sinumerik_eec.ini");
}

TEST(CompensationGolden, heidenhainCom) {
    expectGolden(exportHeidenhain(unidirectional(), {}), "heidenhain.com");
    expectGolden(exportHeidenhain(bidirectional(), {}), "heidenhain_bidirectional.com");
}

TEST(CompensationGolden, csv) {
    expectGolden(exportCsv(unidirectional()), "table.csv");
    expectGolden(exportCsv(bidirectional()), "table_bidirectional.csv");
}

}  // namespace
}  // namespace driftlab::compensation
