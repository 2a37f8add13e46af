// What LinuxCNC 2.9 needs of a COMP_FILE, each pinned: it reads rows until the
// first line that is not three numbers and stops there silently, keeps at
// most 256 entries per joint, and wants strictly increasing nominals.

#include <gtest/gtest.h>

#include "core/compensation/LinuxCncExport.h"
#include "tests/compensation/CompensationTestData.h"

namespace driftlab::compensation {
namespace {

using test::handTable;

CompensationTable evenTable(int points) {
    std::vector<double> x, c;
    for (int i = 0; i < points; ++i) {
        x.push_back(i * 2.5);
        c.push_back(std::sin(i * 0.1) * 4);
    }
    return handTable(x, c);
}

/// Every line as LinuxCNC's usrmotLoadComp reads it: three numbers or stop.
void expectEveryLineReadable(const QByteArray& text, int rows) {
    ASSERT_TRUE(text.endsWith('\n'));
    const QList<QByteArray> lines = text.chopped(1).split('\n');
    ASSERT_EQ(lines.size(), rows);
    double previous = -1e300;
    for (const QByteArray& line : lines) {
        const QList<QByteArray> fields = line.split(' ');
        ASSERT_EQ(fields.size(), 3) << line.constData();
        for (const QByteArray& field : fields) {
            bool ok = false;
            field.toDouble(&ok);
            EXPECT_TRUE(ok) << line.constData();
        }
        EXPECT_FALSE(line.startsWith('#') || line.startsWith(';') || line.trimmed().isEmpty());
        EXPECT_GT(fields[0].toDouble(), previous) << line.constData();
        previous = fields[0].toDouble();
    }
}

TEST(LinuxCncFormat, noBlankOrCommentLineAndAscendingNominal) {
    for (LinuxCncType type : {LinuxCncType::Type0, LinuxCncType::Type1}) {
        const ExportResult r = exportLinuxCnc(evenTable(256), type);
        ASSERT_TRUE(r.ok()) << qPrintable(r.error);
        expectEveryLineReadable(r.text, 256);
    }
}

TEST(LinuxCncFormat, moreThan256RowsRefusedNamingTheLimit) {
    const ExportResult r = exportLinuxCnc(evenTable(300), LinuxCncType::Type0);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.text.isEmpty());
    EXPECT_EQ(r.error, QStringLiteral("LinuxCNC takes at most 256 compensation rows per joint; "
                                      "this table has 300 points: use a larger spacing"));
}

TEST(LinuxCncFormat, nominalsThatPrintAlikeAreRefused) {
    const ExportResult r =
        exportLinuxCnc(handTable({0, 0.00001, 1}, {0, 0, 0}), LinuxCncType::Type1);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.error.contains(QStringLiteral("both print as nominal 0.0000 mm")));
}

// The worked example: deviation +3 µm at 100 mm, both directions, no reversal.
// Correction −3 µm. LinuxCNC's motor command = commanded + trim, with
// type 1: trim = the file's value → −0.0030;
// type 0: trim = nominal − actual, so actual = nominal + 0.003 = 100.0030.
TEST(LinuxCncFormat, signOfTheWorkedExample) {
    CompensationTable t = handTable({0, 100, 200}, {0, -3, 0});
    t.mean_reversal_um = 0;
    EXPECT_EQ(exportLinuxCnc(t, LinuxCncType::Type0).text,
              QByteArray("0.0000 0.0000 0.0000\n100.0000 100.0030 100.0030\n"
                         "200.0000 200.0000 200.0000\n"));
    EXPECT_EQ(exportLinuxCnc(t, LinuxCncType::Type1).text,
              QByteArray("0.0000 0.0000 0.0000\n100.0000 -0.0030 -0.0030\n"
                         "200.0000 0.0000 0.0000\n"));
}

}  // namespace
}  // namespace driftlab::compensation
