// Inputs driftlab-cli must refuse by name and with the reason, leaving the
// store as it was: bundle files that are not regular files, the staging folder
// of a killed export, a store another process keeps locked, a disk that fills
// up during an import, misspelt keys in campaign.json, cells that would break
// the message line, integers out of range. Each case runs the real CLI on real
// files and checks the exit code, the one-line reason and the store.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>

#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"
#include "tests/db/StoreTestSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// A store holding the example campaign, and its bytes before the command under test.
struct StoreWithCampaign {
    explicit StoreWithCampaign(const QTemporaryDir& dir)
        : path(dir.filePath(QStringLiteral("lab.sqlite"))) {
        const CliResult r =
            runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), path});
        EXPECT_EQ(r.exitCode, 0) << r.err.constData();
        sha256 = sha256OfFile(path);
    }
    QString path;
    QByteArray sha256;
};

/// Replaces `path` by a FIFO: opening it for reading waits for a writer that never comes.
void makeFifo(const QString& path) {
    QFile::remove(path);
    ASSERT_EQ(mkfifo(QFile::encodeName(path).constData(), 0644), 0) << qPrintable(path);
}

QByteArray expected(const char* command, const QString& path, const char* why) {
    return QStringLiteral("driftlab-cli %1: %2: %3")
        .arg(QLatin1String(command), path, QString::fromUtf8(why))
        .toUtf8();
}

/// `info` and `import` of `bundle` both fail with `why` at `where`, and the
/// store is untouched.
void expectInfoAndImportRefuse(const QString& bundle, const StoreWithCampaign& store,
                               const QString& where, const char* why) {
    const CliResult info = runCli({QStringLiteral("info"), bundle});
    EXPECT_EQ(info.exitCode, 1);
    EXPECT_EQ(reason(info.err), expected("info", where, why));
    const CliResult import =
        runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), store.path});
    EXPECT_EQ(import.exitCode, 1);
    EXPECT_EQ(reason(import.err), expected("import", where, why));
    EXPECT_EQ(sha256OfFile(store.path), store.sha256)
        << "a refused import must not touch the store";
}

/// The one JSON line of a batch of one item.
QJsonObject batchLine(const CliResult& r) {
    return QJsonDocument::fromJson(r.out.trimmed()).object();
}

}  // namespace

class FifoInBundle : public ::testing::TestWithParam<const char*> {};

TEST_P(FifoInBundle, infoImportAndBatchRefuseItByNameWithoutWaiting) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    const QString bundle = dir.filePath(QStringLiteral("bundle"));
    copyBundle(exampleBundlePath(), bundle);
    const QString fifo = QDir(bundle).filePath(QLatin1String(GetParam()));
    makeFifo(fifo);
    const char* why = "cannot open: a FIFO (named pipe), not a regular file";

    expectInfoAndImportRefuse(bundle, store, fifo, why);

    const CliResult batch =
        runCli({QStringLiteral("batch"), bundle, QStringLiteral("--what"), QStringLiteral("info"),
                QStringLiteral("--timeout-s"), QStringLiteral("60")});
    EXPECT_EQ(batch.exitCode, 1) << batch.err.constData();
    const QJsonObject line = batchLine(batch);
    EXPECT_FALSE(line[QStringLiteral("ok")].toBool(true));
    EXPECT_EQ(line[QStringLiteral("error")].toString(),
              QStringLiteral("%1: %2").arg(fifo, QLatin1String(why)));
}

INSTANTIATE_TEST_SUITE_P(EveryBundleFile, FifoInBundle,
                         ::testing::Values("campaign.json", "samples.csv", "positioning.csv",
                                           "motion.csv"),
                         [](const auto& info) {
                             return QString::fromLatin1(info.param)
                                 .replace(QLatin1Char('.'), QLatin1Char('_'))
                                 .toStdString();
                         });

TEST(BundleRefusalCli, aFifoGivenAsTheBundleOrTheStoreIsRefusedByName) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    const QString fifo = dir.filePath(QStringLiteral("bundle.zip"));
    makeFifo(fifo);

    const CliResult info = runCli({QStringLiteral("info"), fifo});
    EXPECT_EQ(info.exitCode, 1);
    EXPECT_EQ(reason(info.err),
              expected("info", fifo, "a FIFO (named pipe), not a bundle folder or .zip archive"));
    const CliResult import =
        runCli({QStringLiteral("import"), fifo, QStringLiteral("--db"), store.path});
    EXPECT_EQ(import.exitCode, 1);
    EXPECT_EQ(reason(import.err),
              expected("import", fifo, "a FIFO (named pipe), not a bundle folder or .zip archive"));
    EXPECT_EQ(sha256OfFile(store.path), store.sha256);

    const QString fifoStore = dir.filePath(QStringLiteral("pipe.sqlite"));
    makeFifo(fifoStore);
    const CliResult intoFifo =
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), fifoStore});
    EXPECT_EQ(intoFifo.exitCode, 1);
    EXPECT_EQ(reason(intoFifo.err),
              expected("import", fifoStore, "a FIFO (named pipe), not a DriftLab store"));
    const CliResult infoOfFifo = runCli({QStringLiteral("info"), QStringLiteral("--db"), fifoStore,
                                         QStringLiteral("--campaign"), QStringLiteral("1")});
    EXPECT_EQ(infoOfFifo.exitCode, 1);
    EXPECT_EQ(reason(infoOfFifo.err),
              expected("info", fifoStore, "a FIFO (named pipe), not a DriftLab store"));
    EXPECT_EQ(QFileInfo(fifoStore).isFile(), false) << "the FIFO must be left as it was";
}

TEST(BundleRefusalCli, aKilledExportsStagingFolderIsRefusedAndSweptByTheNextExport) {
    QTemporaryDir dir;
    const StoreWithCampaign other(dir);
    const QString big = dir.filePath(QStringLiteral("big"));
    // 400 000 sample times: an export long enough to be killed while it writes.
    ASSERT_FALSE(bundle::writeBundle(generatedCampaign(400'000, 3), big));
    const QString db = dir.filePath(QStringLiteral("big.sqlite"));
    ASSERT_EQ(runCli({QStringLiteral("import"), big, QStringLiteral("--db"), db}).exitCode, 0);
    const QString out = dir.filePath(QStringLiteral("out"));
    const QStringList exportArgs{
        QStringLiteral("export"), QStringLiteral("--db"),  db, QStringLiteral("--campaign"),
        QStringLiteral("1"),      QStringLiteral("--out"), out};

    // Killed (as by the OOM killer or a power cut) once its staging folder is locked.
    QProcess exporter;
    exporter.start(QStringLiteral(DRIFTLAB_CLI), exportArgs);
    QString staging;
    QElapsedTimer waited;
    waited.start();
    while (staging.isEmpty() && exporter.state() != QProcess::NotRunning &&
           waited.elapsed() < 120'000) {
        for (const QString& name :
             QDir(dir.path())
                 .entryList({QStringLiteral("out.partial-*")}, QDir::Dirs | QDir::Hidden))
            if (QFileInfo::exists(dir.filePath(name + QLatin1Char('/') + bundle::kExportLockFile)))
                staging = dir.filePath(name);
        QThread::msleep(1);
    }
    ASSERT_FALSE(staging.isEmpty()) << "the export ended before it could be killed";
    exporter.kill();
    ASSERT_TRUE(exporter.waitForFinished(10'000));
    ASSERT_EQ(exporter.exitStatus(), QProcess::CrashExit);
    ASSERT_FALSE(QFileInfo::exists(out)) << "a killed export must leave no bundle at --out";

    const QString lock = QDir(staging).filePath(bundle::kExportLockFile);
    const char* why =
        "the staging folder of an export that has not finished (killed, or still writing), not a "
        "bundle; the next export to the same folder removes a killed one";
    expectInfoAndImportRefuse(staging, other, lock, why);
    const CliResult batch = runCli(
        {QStringLiteral("batch"), staging, QStringLiteral("--what"), QStringLiteral("info")});
    EXPECT_EQ(batch.exitCode, 1);
    EXPECT_EQ(batchLine(batch)[QStringLiteral("error")].toString(),
              QStringLiteral("%1: %2").arg(lock, QLatin1String(why)));

    // The next export to the same folder removes it: the process that owned it is gone.
    const CliResult again = runCli(exportArgs);
    EXPECT_EQ(again.exitCode, 0) << again.err.constData();
    EXPECT_FALSE(QFileInfo::exists(staging)) << qPrintable(staging);
    EXPECT_TRUE(QDir(dir.path())
                    .entryList({QStringLiteral("out.partial-*")}, QDir::Dirs | QDir::Hidden)
                    .isEmpty());
    EXPECT_EQ(runCli({QStringLiteral("info"), out}).exitCode, 0);
}

TEST(BundleRefusalCli, aStoreAnotherProcessKeepsLockedIsWaitedForThenNamedAsInUse) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    const QByteArray inUse = store.path.toUtf8() +
                             ": in use by another process (it kept the store locked for more "
                             "than 5 s); the store is unchanged";
    {
        // As `sqlite3 lab.sqlite` in BEGIN IMMEDIATE would hold it: writers wait.
        const HeldStoreLock held(store.path, QStringLiteral("BEGIN IMMEDIATE"));
        ASSERT_TRUE(held.locked);
        QElapsedTimer waited;
        waited.start();
        const CliResult import = runCli({QStringLiteral("import"), QStringLiteral("--again"),
                                         exampleBundlePath(), QStringLiteral("--db"), store.path});
        EXPECT_GE(waited.elapsed(), db::kStoreBusyTimeout_ms - 100) << "the busy timeout applies";
        EXPECT_EQ(import.exitCode, 1);
        EXPECT_EQ(reason(import.err), "driftlab-cli import: " + inUse);
        const CliResult run = runCli(
            {QStringLiteral("run"), QStringLiteral("--procedure"),
             QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/procedures/etve-8h.json"),
             QStringLiteral("--rig"), QStringLiteral("sim"), QStringLiteral("--db"), store.path});
        EXPECT_EQ(run.exitCode, 1);
        EXPECT_EQ(reason(run.err), "driftlab-cli run: " + inUse);
        EXPECT_EQ(sha256OfFile(store.path), store.sha256);
    }

    // A lock released within the busy timeout only delays the import.
    auto held = std::make_unique<HeldStoreLock>(store.path, QStringLiteral("BEGIN IMMEDIATE"));
    ASSERT_TRUE(held->locked);
    QProcess import;
    import.start(QStringLiteral(DRIFTLAB_CLI),
                 {QStringLiteral("import"), QStringLiteral("--again"), exampleBundlePath(),
                  QStringLiteral("--db"), store.path});
    ASSERT_TRUE(import.waitForStarted());
    QThread::msleep(1000);
    held.reset();
    ASSERT_TRUE(import.waitForFinished(60'000));
    EXPECT_EQ(import.exitCode(), 0) << import.readAllStandardError().constData();
    EXPECT_EQ(import.readAllStandardOutput().trimmed(), QByteArray("2"));
}

TEST(BundleRefusalCli, anImportOntoAFullDiskSaysSoAndLeavesTheStoreWithItsCampaign) {
    const QString unshare = QStandardPaths::findExecutable(QStringLiteral("unshare"));
    QTemporaryDir dir;
    const QString mount = dir.filePath(QStringLiteral("small-disk"));
    QDir().mkpath(mount);
    auto inSmallDisk = [&](const QString& script, const QStringList& args) {
        QProcess p;
        // A tmpfs of 300 KiB in a mount namespace of its own: the store (about
        // 240 KiB) fits, the campaign to import does not.
        p.start(unshare,
                QStringList{QStringLiteral("-rm"), QStringLiteral("sh"), QStringLiteral("-c"),
                            QStringLiteral("mount -t tmpfs -o size=300k tmpfs \"$1\" && ") + script,
                            QStringLiteral("sh"), mount} +
                    args);
        EXPECT_TRUE(p.waitForFinished(120'000));
        return CliResult{p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
                         p.readAllStandardOutput(), p.readAllStandardError()};
    };
    if (unshare.isEmpty() || inSmallDisk(QStringLiteral("true"), {}).exitCode != 0)
        GTEST_SKIP() << "needs unshare -rm and a tmpfs mount in a user namespace";

    const StoreWithCampaign store(dir);
    const QString big = dir.filePath(QStringLiteral("big"));
    ASSERT_FALSE(bundle::writeBundle(generatedCampaign(20'000), big));
    const QString after = dir.filePath(QStringLiteral("after"));
    QDir().mkpath(after);
    // The store is copied onto the small disk, imported into, and copied back
    // (with any -wal or -shm beside it) for the checks: the tmpfs ends with the namespace.
    const CliResult r = inSmallDisk(
        QStringLiteral(
            "cp \"$2\" \"$1/lab.sqlite\" && \"$3\" import \"$4\" --db \"$1/lab.sqlite\"; "
            "code=$?; cp \"$1\"/lab.sqlite* \"$5\"/ && exit $code"),
        {store.path, QStringLiteral(DRIFTLAB_CLI), big, after});
    const QString onSmallDisk = mount + QStringLiteral("/lab.sqlite");
    EXPECT_EQ(r.exitCode, 1) << r.err.constData();
    EXPECT_EQ(reason(r.err), "driftlab-cli import: " + onSmallDisk.toUtf8() +
                                 ": disk full: nothing of 'generated 20000 rows' was imported; "
                                 "the store is unchanged");

    const QString copy = after + QStringLiteral("/lab.sqlite");
    EXPECT_EQ(folderEntries(after), QStringList{QStringLiteral("lab.sqlite")})
        << "the store is closed cleanly: no -wal or -shm";
    QString error;
    auto reopened = db::CampaignStore::open(copy, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reopened) << qPrintable(error);
    QSqlQuery q(reopened->database());
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA integrity_check")) && q.next());
    EXPECT_EQ(q.value(0).toString(), QStringLiteral("ok"));
    const auto campaigns = reopened->listCampaigns();
    ASSERT_EQ(campaigns.size(), 1u);
    EXPECT_EQ(campaigns[0].name, QStringLiteral("X axis moving-state example"));
}

/// A copy of the example bundle in `dir` with `file`'s `what` replaced by `with`.
QString brokenBundle(const QTemporaryDir& dir, const char* file, const QByteArray& what,
                     const QByteArray& with) {
    const QString bundle = dir.filePath(QStringLiteral("bundle"));
    copyBundle(exampleBundlePath(), bundle);
    replaceInFile(QDir(bundle).filePath(QLatin1String(file)), what, with);
    return bundle;
}

TEST(BundleRefusalCli, aMisspeltScrewKeyIsRefusedAndOtherUnknownKeysAreNamedOrKept) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    const QString bundle = brokenBundle(dir, "campaign.json", "\"alpha_per_K\"", "\"alpha_perK\"");
    const char* why =
        "screw.alpha_perK: unknown key (did you mean 'alpha_per_K'? without it, alpha_per_K "
        "would be 1.15e-05 per K)";
    const QString json = QDir(bundle).filePath(QStringLiteral("campaign.json"));
    expectInfoAndImportRefuse(bundle, store, json, why);

    // Where the default changes nothing, a misspelling is a warning; another
    // tool's key at the top level is kept without a word.
    QTemporaryDir other;
    const QString warned = brokenBundle(other, "campaign.json", "\"location\": \"nut flank\"",
                                        "\"locaton\": \"nut flank\"");
    replaceInFile(QDir(warned).filePath(QStringLiteral("campaign.json")), "\"nut_length_mm\"",
                  "\"operator\": {\"name\": \"A. Engineer\"}, \"nut_length_mm\"");
    const CliResult read = runCli({QStringLiteral("info"), warned});
    EXPECT_EQ(read.exitCode, 0) << read.err.constData();
    QByteArrayList warnings;
    for (const QByteArray& line : read.err.split('\n'))
        if (line.startsWith("warning: ")) warnings << line;
    EXPECT_EQ(warnings, QByteArrayList{"warning: campaign.json: channels[0].locaton: unknown key, "
                                       "kept as is (did you mean 'location'?)"})
        << read.err.constData();
}

TEST(BundleRefusalCli, aCellWithANulOrOfThreeMegabytesIsShownEscapedAndShortened) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    {
        const QString bundle =
            brokenBundle(dir, "samples.csv", "\nS1,20,", QByteArray("\nS1,20,x\0y", 10));
        const CliResult info = runCli({QStringLiteral("info"), bundle});
        EXPECT_EQ(info.exitCode, 1);
        EXPECT_EQ(reason(info.err),
                  expected("info", QDir(bundle).filePath(QStringLiteral("samples.csv:4:3")),
                           "non-numeric cell 'x\\0y20.08' in column 'T_nut'"));
    }
    QTemporaryDir big;
    const QString bundle =
        brokenBundle(big, "samples.csv", "\nS1,20,", '\n' + QByteArray(3'000'000, 'A') + ",20,");
    const CliResult import =
        runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), store.path});
    EXPECT_EQ(import.exitCode, 1);
    EXPECT_EQ(reason(import.err),
              expected("import", QDir(bundle).filePath(QStringLiteral("samples.csv:4:1")),
                       "unknown run id "
                       "'AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA…' (3000000 "
                       "bytes) (not in campaign.json)"));
    EXPECT_LT(import.err.size(), 1000) << "the cell must not be echoed whole";
    EXPECT_EQ(sha256OfFile(store.path), store.sha256)
        << "a refused import must not touch the store";
}

TEST(BundleRefusalCli, aCycleBeyondTheIntegerRangeIsNamedOutOfRangeWithTheRange) {
    QTemporaryDir dir;
    const StoreWithCampaign store(dir);
    const QString bundle = brokenBundle(dir, "positioning.csv", "\nS1,0,0,0,+,0.13\n",
                                        "\nS1,0,99999999999,0,+,0.13\n");
    const QString where = QDir(bundle).filePath(QStringLiteral("positioning.csv:2:3"));
    const char* why =
        "value '99999999999' in column 'cycle' is out of range: an integer from 0 to 2147483647 "
        "is expected";
    expectInfoAndImportRefuse(bundle, store, where, why);
}
