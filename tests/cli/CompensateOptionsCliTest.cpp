// driftlab-cli compensate's table options on the example bundle: the sign
// and the values a format holds, refusals of what it cannot hold, the
// warning on targets at one phase of the screw lead, and re-compensation of
// an active table by the residual measured with it switched on.

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

CliResult compensateWithOptions(QStringList args) {
    return runCli(QStringList{QStringLiteral("compensate"), exampleBundlePath()} + args);
}

/// The data rows of a CSV as (position, first value column).
std::vector<std::pair<double, double>> valueRows(const QByteArray& csv) {
    std::vector<std::pair<double, double>> rows;
    QList<QByteArray> lines = csv.trimmed().split('\n');
    lines.removeFirst();
    for (const QByteArray& line : lines) {
        const QList<QByteArray> f = line.split(',');
        rows.emplace_back(f[0].toDouble(), f[1].toDouble());
    }
    return rows;
}

}  // namespace

TEST(CompensateOptionsCli, signErrorAndIncrementalValuesAreTheCorrectionTurned) {
    QTemporaryDir dir;
    const QString correction = dir.filePath("c.csv"), error = dir.filePath("e.csv"),
                  increments = dir.filePath("i.csv");
    ASSERT_EQ(compensateWithOptions({"--format", "csv", "--out", correction}).exitCode, 0);
    const CliResult e =
        compensateWithOptions({"--format", "csv", "--out", error, "--sign", "error", "--json"});
    ASSERT_EQ(e.exitCode, 0) << e.err.constData();
    EXPECT_EQ(QJsonDocument::fromJson(e.out).object()["value_sign"].toString(), "error");
    ASSERT_EQ(
        compensateWithOptions({"--format", "csv", "--out", increments, "--values", "incremental"})
            .exitCode,
        0);
    EXPECT_TRUE(readFile(error).startsWith("position_mm,error_um,"));
    EXPECT_TRUE(readFile(increments).startsWith("position_mm,correction_increment_um,"));
    const auto c = valueRows(readFile(correction)), err = valueRows(readFile(error)),
               inc = valueRows(readFile(increments));
    ASSERT_EQ(c.size(), err.size());
    ASSERT_EQ(c.size(), inc.size());
    double sum = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        EXPECT_NEAR(err[i].second, -c[i].second, 1e-9) << i;
        sum += inc[i].second;
        EXPECT_NEAR(sum, c[i].second, 0.0005 * double(i + 1)) << i;
    }
}

TEST(CompensateOptionsCli, anOptionTheFormatCannotHoldIsAUsageError) {
    QTemporaryDir dir;
    const QString out = dir.filePath("x");
    const CliResult sign =
        compensateWithOptions({"--format", "sinumerik", "--out", out, "--sign", "correction"});
    EXPECT_EQ(sign.exitCode, 2);
    EXPECT_EQ(reason(sign.err),
              QByteArray("driftlab-cli compensate: --sign correction: sinumerik holds the error "
                         "only: Sinumerik corrects the actual value: a positive compensation value "
                         "moves the axis in the negative direction"));
    const CliResult values =
        compensateWithOptions({"--format", "fanuc", "--out", out, "--values", "absolute"});
    EXPECT_EQ(values.exitCode, 2);
    EXPECT_TRUE(reason(values.err).contains("--values absolute: fanuc holds incremental values"));
    const CliResult both =
        compensateWithOptions({"--format", "sinumerik", "--out", out, "--bidirectional"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_TRUE(reason(both.err).contains("--bidirectional: sinumerik holds one combined table"));
    EXPECT_EQ(compensateWithOptions({"--format", "csv", "--out", out, "--sign", "both"}).exitCode,
              2);
    EXPECT_FALSE(QFile::exists(out));
}

// The example's targets are every 70 mm on a 10 mm lead: one phase.
TEST(CompensateOptionsCli, targetsOnMultiplesOfTheLeadWarn) {
    QTemporaryDir dir;
    const CliResult r = compensateWithOptions({"--format", "csv", "--out", dir.filePath("x.csv")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(
        r.err.contains("warning: the 11 measured targets (0.000 to 700.000 mm) all lie "
                       "0.000 mm past a multiple of the 10.000 mm screw lead"))
        << r.err.constData();
}

// The active table is the run's own table: the residual then is the same
// error again, so the new table is twice the old and the change is the old.
TEST(CompensateOptionsCli, activeTablePlusTheResidualShowsTheChangePerPoint) {
    QTemporaryDir dir;
    const QString active = dir.filePath("active.comp"), next = dir.filePath("next.comp");
    ASSERT_EQ(compensateWithOptions({"--format", "linuxcnc-type1", "--out", active}).exitCode, 0);
    const CliResult r = compensateWithOptions(
        {"--format", "linuxcnc-type1", "--out", next, "--active-table", active, "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject table = QJsonDocument::fromJson(r.out).object()["active_table"].toObject();
    EXPECT_EQ(table["layout"].toString(), "LinuxCNC COMP_FILE_TYPE 1");
    const QJsonArray changes = table["changes"].toArray();
    ASSERT_EQ(changes.size(), 11);
    for (const QJsonValue& c : changes) {
        EXPECT_NEAR(c["new_um"].toDouble(), 2 * c["old_um"].toDouble(), 0.06);
        EXPECT_NEAR(c["change_um"].toDouble(), c["old_um"].toDouble(), 0.06);
    }
    const QList<QByteArray> before = readFile(active).trimmed().split('\n');
    const QList<QByteArray> after = readFile(next).trimmed().split('\n');
    ASSERT_EQ(before.size(), after.size());
    for (qsizetype i = 0; i < before.size(); ++i)
        EXPECT_NEAR(after[i].split(' ')[1].toDouble(), 2 * before[i].split(' ')[1].toDouble(),
                    0.00015)
            << after[i].constData();
    const CliResult text = compensateWithOptions(
        {"--format", "linuxcnc-type1", "--out", next, "--active-table", active});
    EXPECT_TRUE(
        text.out.contains("change from the active table (LinuxCNC COMP_FILE_TYPE 1, 11 "
                          "points; correction, µm):"))
        << text.out.constData();
    // The limits hold for the sum: twice the table breaks a limit the table kept.
    const CliResult limited =
        compensateWithOptions({"--format", "linuxcnc-type1", "--out", next, "--active-table",
                               active, "--max-value-um", "3"});
    EXPECT_EQ(limited.exitCode, 1);
    EXPECT_TRUE(reason(limited.err).contains("(max value)")) << limited.err.constData();
}

// LinuxCNC would stop reading at the comment and run with half a table: the
// file is refused, naming the line, and nothing is written.
TEST(CompensateOptionsCli, anActiveTableLinuxCncWouldTruncateIsRefused) {
    QTemporaryDir dir;
    const QString active = dir.filePath("active.comp"), next = dir.filePath("next.comp");
    writeFile(active, "0.0000 0.0010 0.0010\n; measured cold\n700.0000 0.0020 0.0020\n");
    const CliResult r = compensateWithOptions(
        {"--format", "linuxcnc-type1", "--out", next, "--active-table", active});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), "driftlab-cli compensate: --active-table: " + active.toUtf8() +
                                 ":2: '; measured cold' is not 'nominal second third' (LinuxCNC "
                                 "would stop reading the table here)");
    EXPECT_FALSE(QFile::exists(next));
}
