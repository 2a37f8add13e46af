// Flagged samples end to end on a real store: a simulated campaign whose
// T_bearing_fixed shorts (−50 °C, the module's clamp) for 60 s of run S1 is
// imported; `health --store` stores the flag; `fit` then leaves those samples
// out, says so, and gives the fit of the campaign with those samples removed,
// while `fit --keep-flagged` gives the fit of the data as logged. Without
// stored flags nothing changes.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

/// A copy of `from` with T_bearing_fixed of S1 set to `value` for 700 ≤ t ≤ 750 s
/// (six 10 s samples around the first measuring cycle).
QString withShortedSensor(const QString& from, const QString& target, const QByteArray& value) {
    copyBundle(from, target);
    QList<QByteArray> lines = readFile(target + "/samples.csv").split('\n');
    const QList<QByteArray> header = lines[0].split(',');
    const int column = int(header.indexOf("T_bearing_fixed"));
    EXPECT_GT(column, 1);
    int changed = 0;
    for (int i = 1; i < lines.size(); ++i) {
        QList<QByteArray> f = lines[i].split(',');
        if (f.size() < header.size() || f[0] != "S1") continue;
        const double t = f[1].toDouble();
        if (t < 700 || t > 750) continue;
        f[column] = value;
        lines[i] = f.join(',');
        ++changed;
    }
    EXPECT_EQ(changed, 6);
    writeFile(target + "/samples.csv", lines.join('\n'));
    return target;
}

struct Fit {
    QJsonObject parameters;
    QByteArray err;
};

Fit fit(const QStringList& source, const QStringList& extra = {}) {
    const CliResult r =
        runCli(QStringList{"fit"} + source + QStringList{"--model", "mlr", "--json"} + extra);
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return {QJsonDocument::fromJson(r.out).object()["parameters"].toObject(), r.err};
}

const QByteArray kFlagsLine = "flags: 6 samples of 1 channel left out (--keep-flagged to use them)";

}  // namespace

TEST(SampleFlagCli, flaggedSamplesAreStoredAndLeftOutOfTheFitUnlessKept) {
    QTemporaryDir dir;
    const QString& clean = simulatedCampaign("S1,S3", 3);
    const QString broken = withShortedSensor(clean, dir.filePath("broken"), "-50");
    const QString removed = withShortedSensor(clean, dir.filePath("removed"), "");
    const QString db = dir.filePath("lab.sqlite");
    CliResult r = runCli({"import", "--db", db, broken});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QStringList stored{"--db", db, "--campaign", "1"};

    // No flags stored: exactly as before, and no word about flags.
    const Fit asLogged = fit({broken});
    const Fit before = fit(stored);
    EXPECT_EQ(before.parameters, asLogged.parameters);
    EXPECT_FALSE(before.err.contains("flags:")) << before.err.constData();

    r = runCli(QStringList{"health"} + stored + QStringList{"--store"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.out.contains("S1  T_bearing_fixed: out_of_range, 6 samples: 700.0–750.0 s"))
        << r.out.constData();

    const Fit masked = fit(stored);
    EXPECT_TRUE(masked.err.contains(kFlagsLine)) << masked.err.constData();
    const Fit withoutThem = fit({removed});
    EXPECT_FALSE(masked.parameters.isEmpty());
    EXPECT_EQ(masked.parameters, withoutThem.parameters);
    EXPECT_NE(masked.parameters, asLogged.parameters);

    const Fit kept = fit(stored, {"--keep-flagged"});
    EXPECT_EQ(kept.parameters, asLogged.parameters);
    EXPECT_FALSE(kept.err.contains("flags:")) << kept.err.constData();

    // The other model commands leave them out too.
    r = runCli(QStringList{"compare"} + stored + QStringList{"--models", "mlr", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.err.contains(kFlagsLine)) << r.err.constData();

    // Health reads the data as logged, flagged or not, and finds the same again.
    r = runCli(QStringList{"health"} + stored + QStringList{"--store"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.out.contains("6 samples")) << r.out.constData();
    EXPECT_TRUE(fit(stored).err.contains(kFlagsLine));
}

TEST(SampleFlagCli, storingFlagsNeedsAStore) {
    const CliResult r = runCli({"health", exampleBundlePath(), "--store"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("--db")) << r.err.constData();
}
