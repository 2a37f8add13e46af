// Every bad-input class of the bundle format gives an error naming file,
// line and column, and returns no campaign (issue #2).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <QTemporaryDir>
#include <chrono>
#include <cmath>
#include <future>

#include "core/bundle/BundleReader.h"
#include "tests/support/BadBundleCases.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;

class BadBundle : public ::testing::TestWithParam<BadBundleCase> {};

TEST_P(BadBundle, isRejectedWithFileLineColumnAndReason) {
    const BadBundleCase& bad = GetParam();
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    bad.breakIt(dir.path());

    bundle::BundleReadResult result = bundle::readBundle(dir.path());
    EXPECT_FALSE(result.ok());
    ASSERT_TRUE(result.error.has_value());
    const QString text = result.error->toString();
    EXPECT_TRUE(text.startsWith(QString::fromUtf8(bad.expectedLocation))) << qPrintable(text);
    EXPECT_TRUE(text.contains(QString::fromUtf8(bad.expectedMessage))) << qPrintable(text);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, BadBundle, ::testing::ValuesIn(badBundleCases()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(BundleReader, missingFolderIsNamed) {
    bundle::BundleReadResult result = bundle::readBundle(QStringLiteral("/nonexistent/bundle"));
    ASSERT_TRUE(result.error);
    EXPECT_EQ(result.error->toString(),
              QStringLiteral("/nonexistent/bundle: no such bundle folder or archive"));
}

TEST(BundleReader, aFifoInTheBundleIsRefusedWithoutWaitingForAWriter) {
    for (const char* name : {"campaign.json", "samples.csv", "positioning.csv", "motion.csv"}) {
        QTemporaryDir dir;
        copyBundle(exampleBundlePath(), dir.path());
        const QByteArray fifo = QFile::encodeName(dir.filePath(QLatin1String(name)));
        ASSERT_EQ(unlink(fifo.constData()), 0);
        ASSERT_EQ(mkfifo(fifo.constData(), 0644), 0);
        auto read = std::async(std::launch::async, [&] { return bundle::readBundle(dir.path()); });
        if (read.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
            // A writer that closes at once ends the reader's wait, so the test can end.
            const int fd = open(fifo.constData(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) close(fd);
            ADD_FAILURE() << "the reader waited for a writer on " << name;
        }
        const bundle::BundleReadResult result = read.get();
        ASSERT_TRUE(result.error) << name;
        EXPECT_EQ(result.error->toString(),
                  QLatin1String(name) +
                      QStringLiteral(": cannot open: a FIFO (named pipe), not a regular file"));
    }
}

TEST(BundleReader, unknownKeysInTheFormatsObjectsAreNamedAndKept) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    const QString json = dir.filePath(QStringLiteral("campaign.json"));
    replaceInFile(json, "\"axis\": \"X\",", "\"axis\": \"X\", \"serial\": \"4711\",");
    replaceInFile(json, "\"kind\": \"moving\",", "\"kind\": \"moving\", \"feed\": 8000,");
    // Top level: another tool's key without a word, a near miss of a given key named.
    replaceInFile(json, "\"nut_length_mm\"",
                  "\"tool\": \"x\", \"nut_lenght_mm\": 80, \"nut_length_mm\"");
    const bundle::BundleReadResult read = bundle::readBundle(dir.path());
    ASSERT_TRUE(read.ok()) << qPrintable(read.error->toString());
    EXPECT_EQ(read.warnings,
              QStringList({QStringLiteral("campaign.json: nut_lenght_mm: unknown key, kept as is "
                                          "(did you mean 'nut_length_mm'?)"),
                           QStringLiteral("campaign.json: machine.serial: unknown key, kept as is "
                                          "(the format's keys here: name, axis, controller)"),
                           QStringLiteral("campaign.json: runs[0].feed: unknown key, kept as is "
                                          "(did you mean 'feed_mm_min'?)")}));
    EXPECT_EQ(read.campaign->machine.extra.value(QStringLiteral("serial")).toString(),
              QStringLiteral("4711"));
    EXPECT_EQ(read.campaign->runs[0].extra.value(QStringLiteral("feed")).toInt(), 8000);
    EXPECT_EQ(read.campaign->extra.value(QStringLiteral("tool")).toString(), QStringLiteral("x"));
}

TEST(BundleReader, feedAxisRunWithoutScrewIsRejected) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    replaceInFile(dir.filePath(QStringLiteral("campaign.json")), "\"nut_length_mm\": 80,", "");
    bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.error);
    EXPECT_EQ(result.error->toString(),
              QStringLiteral("campaign.json: runs[0]: a moving run needs 'screw' and "
                             "'nut_length_mm' in the campaign"));
}

TEST(BundleReader, expansionCoefficientInPpmIsAUnitMixUp) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    replaceInFile(dir.filePath(QStringLiteral("campaign.json")), "1.15e-05", "11.5");
    bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.error);
    EXPECT_TRUE(result.error->toString().startsWith(
        QStringLiteral("campaign.json: screw.alpha_per_K: 11.5 per K")))
        << qPrintable(result.error->toString());
}

TEST(BundleReader, aColumnInFahrenheitOrKelvinIsReadInCelsius) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    const QString samples = dir.filePath(QStringLiteral("samples.csv"));
    rewriteColumn(samples, 2,  // T_nut
                  [](double c) { return QByteArray::number(c * 9 / 5 + 32, 'g', 17); });
    rewriteColumn(samples, 3,  // T_bearing_fixed
                  [](double c) { return QByteArray::number(c + 273.15, 'g', 17); });
    replaceInFile(samples, "run,time_s,T_nut,T_bearing_fixed,",
                  "run,time_s,T_nut [°F],T_bearing_fixed (K),");
    const bundle::BundleReadResult converted = bundle::readBundle(dir.path());
    ASSERT_TRUE(converted.ok()) << qPrintable(converted.error->toString());
    const bundle::BundleReadResult plain = bundle::readBundle(exampleBundlePath());
    ASSERT_TRUE(plain.ok());
    for (const char* id : {"T_nut", "T_bearing_fixed"}) {
        const SampleSeries& want = plain.campaign->runs.front().samples;
        const SampleSeries& got = converted.campaign->runs.front().samples;
        const auto& w = want.values[std::size_t(want.columnIndex(QString::fromLatin1(id)))];
        const auto& g = got.values[std::size_t(got.columnIndex(QString::fromLatin1(id)))];
        ASSERT_EQ(g.size(), w.size()) << id;
        for (std::size_t r = 0; r < w.size(); ++r) {
            EXPECT_EQ(std::isnan(g[r]), std::isnan(w[r])) << id << " row " << r;
            if (!std::isnan(w[r])) {
                EXPECT_NEAR(g[r], w[r], 1e-9) << id << " row " << r;
            }
        }
    }
    const QString warnings = converted.warnings.join(QLatin1Char('\n'));
    EXPECT_TRUE(warnings.contains(
        QStringLiteral("samples.csv: column 'T_nut [°F]': read in °F, converted to °C")))
        << qPrintable(warnings);
    EXPECT_TRUE(warnings.contains(
        QStringLiteral("samples.csv: column 'T_bearing_fixed (K)': read in K, converted to °C")))
        << qPrintable(warnings);
}

TEST(BundleReader, deviationsInMillimetresAreReadWithAWarning) {
    // An export in mm: 0.93 µm written as 0.00093. Each value is possible,
    // so nothing is refused, but a whole run within ±0.1 µm is no real axis.
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    rewriteColumn(dir.filePath(QStringLiteral("positioning.csv")), 5,  // deviation_um
                  [](double um) { return QByteArray::number(um / 1000, 'g', 12); });
    const bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.ok());
    EXPECT_TRUE(
        result.warnings.join(QLatin1Char('\n'))
            .contains(QStringLiteral("positioning.csv: run 'S1': all 154 deviations are "
                                     "within ±0.1 µm (largest 0.03498 µm): mm instead of µm?")))
        << qPrintable(result.warnings.join(QLatin1Char('\n')));
    // The example as written, in µm, gets no such warning.
    copyBundle(exampleBundlePath(), dir.filePath(QStringLiteral("plain")));
    const bundle::BundleReadResult plain =
        bundle::readBundle(dir.filePath(QStringLiteral("plain")));
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(plain.warnings.join(QLatin1Char('\n')).contains(QStringLiteral("mm instead")));
}

TEST(BundleReader, aDriftProbeInMillimetresIsReadWithAWarning) {
    // The spindle run's x probe exported in mm: 1.2 µm written as 0.0012.
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    rewriteColumn(
        dir.filePath(QStringLiteral("samples.csv")), 10,  // D_x
        [](double um) { return QByteArray::number(um / 1000, 'g', 12); }, "SP1");
    const bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.ok());
    const QString warnings = result.warnings.join(QLatin1Char('\n'));
    EXPECT_TRUE(
        warnings.contains(QStringLiteral("samples.csv: run 'SP1': all 181 readings of "
                                         "'D_x' are within ±0.1 µm")))
        << qPrintable(warnings);
    EXPECT_FALSE(warnings.contains(QStringLiteral("'D_y'"))) << qPrintable(warnings);
}

TEST(BundleReader, namesSpelledByHandAreTheNamesTheyMean) {
    // A hand-written campaign.json: "ETVE" as the acronym is written, a role
    // capitalised or with '-' or a space for '_', a mounting in title case, a
    // stroke written from its far end.
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    const QString json = dir.filePath(QStringLiteral("campaign.json"));
    replaceInFile(json, "\"kind\": \"moving\"", "\"kind\": \"Moving\"");
    replaceInFile(json, "\"kind\": \"spindle\"", "\"kind\": \"SPINDLE\"");
    replaceInFile(json, "\"role\": \"nut\"", "\"role\": \"Nut\"");
    replaceInFile(json, "\"role\": \"drift_x\"", "\"role\": \"Drift-X\"");
    replaceInFile(json, "\"role\": \"tilt_a\"", "\"role\": \"tilt a\"");
    replaceInFile(json, "\"quantity\": \"displacement\"", "\"quantity\": \"Displacement\"");
    replaceInFile(json, "\"mounting\": \"fixed-free\"", "\"mounting\": \"Fixed-Free\"");
    replaceInFile(json, "\"range_mm\": [\n        210,\n        490", "\"range_mm\": [490, 210");
    const bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.ok()) << qPrintable(result.error->toString());
    EXPECT_EQ(*result.campaign, exampleCampaign());

    // A name that is none of them lists what is.
    replaceInFile(json, "\"role\": \"Nut\"", "\"role\": \"nut flank\"");
    const bundle::BundleReadResult wrong = bundle::readBundle(dir.path());
    ASSERT_TRUE(wrong.error);
    EXPECT_TRUE(wrong.error->toString().endsWith(QStringLiteral(
        "unknown role 'nut flank' for a temperature channel (expected nut, bearing, ambient, "
        "air, structure, motor, spindle, other)")))
        << qPrintable(wrong.error->toString());
}

TEST(BundleReader, aDeclaredChannelWithoutAColumnAndARunWithoutRecordsAreNamed) {
    // A writer that dropped the air thermometer's column and the spindle run's
    // rows: each is possible, but the user should hear of it.
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    const QString samples = dir.filePath(QStringLiteral("samples.csv"));
    const QList<QByteArray> lines = readFile(samples).split('\n');
    const qsizetype air = lines.front().split(',').indexOf("T_air");
    ASSERT_GT(air, 0);
    QByteArrayList kept;
    for (const QByteArray& line : lines) {
        if (line.startsWith("SP1,") || line.isEmpty()) continue;
        QByteArrayList cells = line.split(',');
        cells.removeAt(air);
        kept << cells.join(',');
    }
    writeFile(samples, kept.join('\n') + '\n');
    const bundle::BundleReadResult result = bundle::readBundle(dir.path());
    ASSERT_TRUE(result.ok()) << qPrintable(result.error->toString());
    EXPECT_TRUE(result.warnings.contains(QStringLiteral(
        "samples.csv: no column for channel(s) 'T_air' of campaign.json: they carry no reading")))
        << qPrintable(result.warnings.join(QLatin1Char('\n')));
    EXPECT_TRUE(result.warnings.contains(
        QStringLiteral("run(s) 'SP1' of campaign.json have no record in any file: no data")))
        << qPrintable(result.warnings.join(QLatin1Char('\n')));
    // The example as written has a column for every channel and rows for every run.
    const bundle::BundleReadResult plain = bundle::readBundle(exampleBundlePath());
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(plain.warnings.join(QLatin1Char('\n')).contains(QStringLiteral("no data")));
    EXPECT_FALSE(plain.warnings.join(QLatin1Char('\n')).contains(QStringLiteral("no column")));
}
