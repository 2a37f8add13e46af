// Bundles as archives and folders (issue 9): Info-ZIP archives with the files
// at the root or in one folder, an archive of a bundle already imported as a
// folder, an axis that overruns its travel to reverse; export never mixes two
// campaigns in one folder and never replaces a folder that is not a bundle.
#include <gtest/gtest.h>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "tests/cli/RealWorldBundleSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(RealWorldBundle, zipArchivesImportFromTheRootOrFromOneFolder) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    copyBundle(exampleBundlePath(), bundle);
    runTool(QStringLiteral("zip"),
            {QStringLiteral("-qr"), dir.filePath(QStringLiteral("root.zip")), QStringLiteral(".")},
            bundle);
    runTool(QStringLiteral("zip"),
            {QStringLiteral("-qr"), QStringLiteral("folder.zip"), QStringLiteral("campaign")},
            dir.path());
    const QDir work(dir.path());
    EXPECT_EQ(importedAndExported(work.filePath(QStringLiteral("root.zip")), work),
              exampleCampaign());
    EXPECT_EQ(importedAndExported(work.filePath(QStringLiteral("folder.zip")), work),
              exampleCampaign());
}

TEST(RealWorldBundle, zipOfABundleAlreadyImportedAsAFolderIsNoticed) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    copyBundle(exampleBundlePath(), bundle);
    runTool(QStringLiteral("zip"),
            {QStringLiteral("-qr"), QStringLiteral("campaign.zip"), QStringLiteral("campaign")},
            dir.path());
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), db}).exitCode, 0);
    const QByteArray before = sha256OfFile(db);
    CliResult again =
        runCli({QStringLiteral("import"), dir.filePath(QStringLiteral("campaign.zip")),
                QStringLiteral("--db"), db});
    EXPECT_EQ(again.exitCode, 1);
    EXPECT_TRUE(reason(again.err).contains("as campaign 1") &&
                reason(again.err).contains("--again imports it once more"))
        << again.err.constData();
    EXPECT_EQ(sha256OfFile(db), before);
}

TEST(RealWorldBundle, overrunPastTheTravelIsAcceptedWithOneWarning) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("overrun"));
    copyBundle(exampleBundlePath(), bundle);
    // ISO 230-2: the axis runs 1.25 mm past the last target to reverse.
    replaceInFile(QDir(bundle).filePath(QStringLiteral("samples.csv")), ",423.333,8000,",
                  ",701.25,8000,");
    replaceInFile(QDir(bundle).filePath(QStringLiteral("samples.csv")), ",343.333,-8000,",
                  ",-3.5,-8000,");
    CliResult r = runCli({QStringLiteral("info"), bundle, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(
        r.err.contains("warning: samples.csv:3: 2 position(s) outside the travel [0, 700] "
                       "mm, up to 3.5 mm past it (overrun to reverse; accepted)"))
        << r.err.constData();
}

TEST(RealWorldBundle, exportNeverMixesTwoCampaignsInOneFolder) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    // Campaign 1 has positioning readings; campaign 2 has none.
    const QString noPositioning = dir.filePath(QStringLiteral("no-positioning"));
    copyBundle(exampleBundlePath(), noPositioning);
    QFile::remove(QDir(noPositioning).filePath(QStringLiteral("positioning.csv")));
    replaceInFile(QDir(noPositioning).filePath(QStringLiteral("campaign.json")),
                  "X axis moving-state example", "Second campaign");
    ASSERT_EQ(runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), db})
                  .exitCode,
              0);
    ASSERT_EQ(
        runCli({QStringLiteral("import"), noPositioning, QStringLiteral("--db"), db}).exitCode, 0);
    const QString out = dir.filePath(QStringLiteral("out"));
    auto exportCampaign = [&](const char* id, bool force) {
        QStringList args{
            QStringLiteral("export"), QStringLiteral("--db"),  db, QStringLiteral("--campaign"),
            QString::fromLatin1(id),  QStringLiteral("--out"), out};
        if (force) args << QStringLiteral("--force");
        return runCli(args);
    };
    ASSERT_EQ(exportCampaign("1", false).exitCode, 0);
    const QByteArray firstExport = readFile(QDir(out).filePath(QStringLiteral("samples.csv")));

    CliResult refused = exportCampaign("2", false);
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_TRUE(reason(refused.err)
                    .contains("is not empty (campaign.json, motion.csv, "
                              "positioning.csv, samples.csv)"))
        << refused.err.constData();
    EXPECT_EQ(readFile(QDir(out).filePath(QStringLiteral("samples.csv"))), firstExport);

    ASSERT_EQ(exportCampaign("2", true).exitCode, 0);
    EXPECT_FALSE(QFile::exists(QDir(out).filePath(QStringLiteral("positioning.csv"))))
        << "a stale file of the first campaign survived the replacement";
    CliResult info = runCli({QStringLiteral("info"), out, QStringLiteral("--json")});
    const QJsonObject json = QJsonDocument::fromJson(info.out).object();
    EXPECT_EQ(json[QStringLiteral("name")].toString(), QStringLiteral("Second campaign"));
    EXPECT_EQ(
        json[QStringLiteral("runs")].toArray()[0].toObject()[QStringLiteral("positioning")].toInt(),
        0);
    EXPECT_TRUE(QDir(dir.path())
                    .entryList({QStringLiteral("out.*")}, QDir::AllEntries | QDir::NoDotAndDotDot)
                    .isEmpty())
        << "staging folders left behind";
}

TEST(RealWorldBundle, forceNeverReplacesAFolderThatIsNotABundle) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), db})
                  .exitCode,
              0);
    const QString home = dir.filePath(QStringLiteral("home"));
    QDir().mkpath(home);
    writeFile(QDir(home).filePath(QStringLiteral("thesis.tex")), "months of work");
    CliResult r =
        runCli({QStringLiteral("export"), QStringLiteral("--db"), db, QStringLiteral("--campaign"),
                QStringLiteral("1"), QStringLiteral("--out"), home, QStringLiteral("--force")});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).contains("holds files that are not a bundle's (thesis.tex)"))
        << r.err.constData();
    EXPECT_EQ(readFile(QDir(home).filePath(QStringLiteral("thesis.tex"))), "months of work");
}
