// Campaign bundles read back exactly what was written (docs/bundles.md).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <QDir>
#include <QLockFile>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "core/bundle/BundleWriter.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(BundleReader, readsTheExampleCampaignWithFeedAxisAndSpindleRuns) {
    bundle::BundleReadResult result = bundle::readBundle(exampleBundlePath());
    ASSERT_TRUE(result.ok()) << qPrintable(result.error->toString());
    const Campaign& c = *result.campaign;
    EXPECT_EQ(c.name, QStringLiteral("X axis moving-state example"));
    ASSERT_TRUE(c.screw);
    EXPECT_DOUBLE_EQ(c.screw->lead_mm, 10);
    EXPECT_DOUBLE_EQ(c.screw->fixed_end_mm, -40);
    EXPECT_EQ(c.channels.size(), 13u);
    ASSERT_EQ(c.runs.size(), 2u);

    const driftlab::Run& s1 = c.runs[0];
    EXPECT_EQ(s1.kind, RunKind::Moving);
    EXPECT_EQ(s1.samples.rowCount(), 361u);
    EXPECT_EQ(s1.positioning.size(), 7u * 22u);
    EXPECT_FALSE(s1.motion.empty());
    // The dropout at row 38 of S1 is a missing sample, not a zero.
    const int bearing = s1.samples.columnIndex(QStringLiteral("T_bearing_fixed"));
    EXPECT_TRUE(std::isnan(s1.samples.values[std::size_t(bearing)][37]));

    const driftlab::Run& sp1 = c.runs[1];
    EXPECT_EQ(sp1.kind, RunKind::Spindle);
    const Channel* probe = c.findChannel(QStringLiteral("D_z"));
    ASSERT_NE(probe, nullptr);
    EXPECT_EQ(probe->quantity, Quantity::Displacement);
    EXPECT_EQ(probe->role, ChannelRole::DriftZ);
    const int dz = sp1.samples.columnIndex(QStringLiteral("D_z"));
    EXPECT_LT(*std::min_element(sp1.samples.values[std::size_t(dz)].begin(),
                                sp1.samples.values[std::size_t(dz)].end()),
              -10.0)
        << "the spindle run's z drift probe carries its thermal drift in µm";
}

TEST(BundleWriter, writeThenReadGivesTheSameCampaignAndTheSameBytes) {
    bundle::BundleReadResult original = bundle::readBundle(exampleBundlePath());
    ASSERT_TRUE(original.ok());
    QTemporaryDir dir;
    ASSERT_FALSE(bundle::writeBundle(*original.campaign, dir.filePath(QStringLiteral("a"))));
    bundle::BundleReadResult again = bundle::readBundle(dir.filePath(QStringLiteral("a")));
    ASSERT_TRUE(again.ok()) << qPrintable(again.error->toString());
    EXPECT_EQ(*again.campaign, *original.campaign);

    ASSERT_FALSE(bundle::writeBundle(*again.campaign, dir.filePath(QStringLiteral("b"))));
    for (const char* name : {"campaign.json", "samples.csv", "motion.csv", "positioning.csv"})
        EXPECT_EQ(readFile(dir.filePath(QStringLiteral("a/") + QLatin1String(name))),
                  readFile(dir.filePath(QStringLiteral("b/") + QLatin1String(name))))
            << name;
}

TEST(BundleWriter, numbersSurviveExactlyIncludingOnesWithoutAShortDecimalForm) {
    Campaign c = generatedCampaign(1000, 3);
    c.runs[0].samples.values[0][5] = 0.1 + 0.2;  // 0.30000000000000004
    c.runs[0].samples.values[1][6] = 1e-300;
    c.runs[0].samples.values[2][7] = std::numeric_limits<double>::quiet_NaN();  // a dropout
    QTemporaryDir dir;
    ASSERT_FALSE(bundle::writeBundle(c, dir.path()));
    bundle::BundleReadResult back = bundle::readBundle(dir.path());
    ASSERT_TRUE(back.ok()) << qPrintable(back.error->toString());
    EXPECT_EQ(*back.campaign, c);
}

TEST(BundleWriter, unknownKeysAreKeptForTheToolThatWroteThem) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    replaceInFile(dir.filePath(QStringLiteral("campaign.json")), "\"nut_length_mm\"",
                  "\"operator\": {\"name\": \"A. Engineer\"}, \"nut_length_mm\"");
    bundle::BundleReadResult read = bundle::readBundle(dir.path());
    ASSERT_TRUE(read.ok());
    EXPECT_TRUE(read.warnings.isEmpty()) << qPrintable(read.warnings.join('\n'));
    EXPECT_EQ(read.campaign->extra.value(QStringLiteral("operator"))
                  .toObject()
                  .value(QStringLiteral("name")),
              QStringLiteral("A. Engineer"));
    ASSERT_FALSE(bundle::writeBundle(*read.campaign, dir.filePath(QStringLiteral("out"))));
    EXPECT_TRUE(
        readFile(dir.filePath(QStringLiteral("out/campaign.json"))).contains("A. Engineer"));
}

TEST(BundleWriter, aKilledExportsStagingFolderIsRefusedAndRemovedByTheNextExportOnly) {
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("out"));
    // As an export killed mid-write leaves it: locked by a process that is gone,
    // samples.csv and motion.csv written, campaign.json (written last) not yet.
    const QString killed = target + QStringLiteral(".partial-Kq81Zx");
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        QDir().mkpath(killed);
        QLockFile lock(QDir(killed).filePath(bundle::kExportLockFile));
        const bool locked = lock.tryLock(0);
        for (const char* name : {"samples.csv", "motion.csv"})
            QFile::copy(QDir(exampleBundlePath()).filePath(QLatin1String(name)),
                        QDir(killed).filePath(QLatin1String(name)));
        _exit(locked ? 0 : 1);  // no unlock: the lock file stays, as after SIGKILL
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    // One this process is writing (its lock is held): neither read nor removed.
    const QString live = target + QStringLiteral(".partial-Lv22Yw");
    copyBundle(exampleBundlePath(), live);
    QLockFile liveLock(QDir(live).filePath(bundle::kExportLockFile));
    ASSERT_TRUE(liveLock.tryLock(0));

    const QString why =
        bundle::kExportLockFile + QStringLiteral(
                                      ": the staging folder of an export that has not "
                                      "finished (killed, or still writing), not a bundle; "
                                      "the next export to the same folder removes a "
                                      "killed one");
    for (const QString& staged : {killed, live}) {
        const bundle::BundleReadResult read = bundle::readBundle(staged);
        ASSERT_FALSE(read.ok()) << qPrintable(staged);
        EXPECT_EQ(read.error->toString(), why);
    }

    ASSERT_FALSE(bundle::writeBundle(exampleCampaign(), target));
    EXPECT_FALSE(QFileInfo::exists(killed)) << "the killed export's folder must be removed";
    EXPECT_TRUE(QFileInfo::exists(QDir(live).filePath(QStringLiteral("campaign.json"))))
        << "a running export's folder must be left alone";
    const bundle::BundleReadResult written = bundle::readBundle(target);
    ASSERT_TRUE(written.ok()) << qPrintable(written.error->toString());
    EXPECT_FALSE(QFileInfo::exists(QDir(target).filePath(bundle::kExportLockFile)));
}

TEST(BundleReader, rowsWithoutAnyValueAreSkippedWithAWarning) {
    QTemporaryDir dir;
    copyBundle(exampleBundlePath(), dir.path());
    replaceInFile(dir.filePath(QStringLiteral("samples.csv")), "\nS1,30,",
                  "\nS1,25,,,,,,,,,,,,,,,,\nS1,30,");
    bundle::BundleReadResult read = bundle::readBundle(dir.path());
    ASSERT_TRUE(read.ok()) << qPrintable(read.error->toString());
    ASSERT_EQ(read.warnings.size(), 1);
    EXPECT_TRUE(
        read.warnings[0].startsWith(QStringLiteral("samples.csv:5: 1 row(s) without any value")))
        << qPrintable(read.warnings[0]);
    EXPECT_EQ(read.campaign->runs[0].samples.rowCount(), 361u);
}

TEST(BundleReader, progressCallbackCanCancelAndNothingIsReturned) {
    QTemporaryDir dir;
    ASSERT_FALSE(bundle::writeBundle(generatedCampaign(200'000), dir.path()));
    int calls = 0;
    bundle::BundleReadOptions options;
    options.progress = [&](double) { return ++calls < 2; };
    bundle::BundleReadResult read = bundle::readBundle(dir.path(), options);
    EXPECT_FALSE(read.ok());
    ASSERT_TRUE(read.error);
    EXPECT_EQ(read.error->message, QStringLiteral("import cancelled"));
    EXPECT_EQ(calls, 2);
}
