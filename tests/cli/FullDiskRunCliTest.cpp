// `driftlab-cli run` into a store whose disk fills up mid-run (an 8 MB tmpfs
// in a private mount namespace, tests/cli/run_on_a_full_disk.sh): the rows
// are held in memory and every commit retried, so an operator who frees
// space loses nothing; one who does not is told what is lost, and the run is
// interrupted, resumable, with what the store took.
#include <gtest/gtest.h>

#include <QProcess>
#include <QTemporaryDir>

#include "db/CampaignStore.h"
#include "db/RunLogger.h"
#include "tests/acquisition/LoggedRunSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

struct FullDiskRun {
    int rc = -1;
    QByteArray err;
    QString store;
};

/// Runs a 3000 s ETVE at 500× while the disk is full; `mode` free or keep.
/// Empty `store` when the sandbox (user and mount namespaces) is not available.
FullDiskRun runOnAFullDisk(const QTemporaryDir& dir, const QString& mode) {
    const QString procedure = dir.filePath(QStringLiteral("etve.json"));
    QFile f(procedure);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "driftlab.procedure/1", "name": "ETVE", "kind": "etve",
        "sample_interval_s": 1, "etve": {"run_id": "E1", "duration_s": 3000}})");
    f.close();
    QProcess p;
    p.start(QStringLiteral("unshare"),
            {"-rm", "sh", DRIFTLAB_SOURCE_DIR "/tests/cli/run_on_a_full_disk.sh", DRIFTLAB_CLI,
             dir.path(), procedure, mode});
    EXPECT_TRUE(p.waitForFinished(120'000));
    FullDiskRun r;
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) return r;
    const QByteArray out = p.readAllStandardOutput();
    const qsizetype at = out.lastIndexOf("rc=");
    if (at < 0) return r;
    r.rc = out.mid(at + 3).trimmed().toInt();
    QFile err(dir.filePath(QStringLiteral("err")));
    EXPECT_TRUE(err.open(QIODevice::ReadOnly));
    r.err = err.readAll();
    r.store = dir.filePath(QStringLiteral("lab.sqlite"));
    return r;
}

bool sandboxAvailable() {
    QProcess p;
    p.start(QStringLiteral("unshare"), {"-rm", "sh", "-c", "mount -t tmpfs tmpfs /mnt"});
    return p.waitForFinished(10'000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

}  // namespace

TEST(FullDiskRunCli, spaceFreedMidRunLosesNoRow) {
    if (!sandboxAvailable()) GTEST_SKIP() << "no user and mount namespaces for a small tmpfs";
    QTemporaryDir dir;
    const FullDiskRun r = runOnAFullDisk(dir, QStringLiteral("free"));
    ASSERT_FALSE(r.store.isEmpty());
    EXPECT_EQ(r.rc, 0) << r.err.constData();
    EXPECT_TRUE(r.err.contains("warning: ") && r.err.contains("database or disk is full") &&
                r.err.contains("free space for it now"))
        << r.err.constData();
    EXPECT_TRUE(r.err.contains("the store takes the rows again; none is lost"))
        << r.err.constData();
    EXPECT_EQ(runStatuses(r.store),
              (QStringList{QStringLiteral("E0=complete"), QStringLiteral("E1=complete")}));
    QString error;
    auto store = db::CampaignStore::open(r.store, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << error.toStdString();
    const auto state = db::loggedRunState(*store, 2, &error);
    ASSERT_TRUE(state) << error.toStdString();
    EXPECT_EQ(state->rows, 3001);  // every second from 0 to 3000 s
    EXPECT_EQ(state->last_sample_s, 3000.0);
}

TEST(FullDiskRunCli, aDiskLeftFullNamesWhatIsLostAndTheRunResumes) {
    if (!sandboxAvailable()) GTEST_SKIP() << "no user and mount namespaces for a small tmpfs";
    QTemporaryDir dir;
    const FullDiskRun r = runOnAFullDisk(dir, QStringLiteral("keep"));
    ASSERT_FALSE(r.store.isEmpty());
    EXPECT_EQ(r.rc, 1) << r.err.constData();
    const QByteArray last = r.err.trimmed().split('\n').last();
    EXPECT_TRUE(last.contains("database or disk is full; the store refused rows for too long: "
                              "run E1 from ") &&
                last.contains("could not be saved and is lost"))
        << last.constData();
    // Opened again (here on a disk with room), the run is interrupted and resumable.
    QString error;
    auto store = db::CampaignStore::open(r.store, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << error.toStdString();
    db::markInterruptedRuns(*store, &error);
    const auto state = db::loggedRunState(*store, 2, &error);
    ASSERT_TRUE(state) << error.toStdString();
    EXPECT_EQ(state->status, QStringLiteral("interrupted"));
    EXPECT_LT(state->end_s(), 3000);
    store.reset();
    const CliResult resumed = runCli({"run", "--procedure", dir.filePath("etve.json"), "--rig",
                                      "sim", "--db", r.store, "--resume", "2"});
    EXPECT_EQ(resumed.exitCode, 0) << resumed.err.constData();
    EXPECT_EQ(runStatuses(r.store),
              (QStringList{QStringLiteral("E0=complete"), QStringLiteral("E1=complete")}));
}
