#pragma once
// A store for the sensor-health tests: a simulated campaign (runs S1, S3)
// whose T_bearing_fixed shorts (−50 °C, the module's clamp) for 700–750 s of
// run S1 (six 10 s samples), imported with the real CLI (campaign 1).
#include <gtest/gtest.h>

#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

namespace driftlab::test {

/// Sets `channel` of run S1 to `value` for from_s ≤ t ≤ to_s in `bundle`'s samples.
inline void setSamples(const QString& bundle, const QByteArray& channel, double from_s, double to_s,
                       const QByteArray& value) {
    QList<QByteArray> lines = readFile(bundle + "/samples.csv").split('\n');
    const int column = int(lines[0].split(',').indexOf(channel));
    ASSERT_GT(column, 1) << channel.constData();
    for (QByteArray& line : lines) {
        QList<QByteArray> f = line.split(',');
        if (f.size() <= column || f[0] != "S1" || f[1].toDouble() < from_s ||
            f[1].toDouble() > to_s)
            continue;
        f[column] = value;
        line = f.join(',');
    }
    writeFile(bundle + "/samples.csv", lines.join('\n'));
}

/// The shorted campaign's bundle, dir/shorted.
inline QString shortedSensorBundle(const QTemporaryDir& dir) {
    const QString bundle = dir.filePath(QStringLiteral("shorted"));
    copyBundle(simulatedCampaign(QStringLiteral("S1,S3"), 3), bundle);
    setSamples(bundle, "T_bearing_fixed", 700, 750, "-50");
    return bundle;
}

/// `bundle` imported with `driftlab-cli import` into dir/lab.sqlite; the store's path.
inline QString importedStore(const QTemporaryDir& dir, const QString& bundle) {
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    const CliResult r = runCli({QStringLiteral("import"), QStringLiteral("--db"), db, bundle});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return db;
}

}  // namespace driftlab::test
