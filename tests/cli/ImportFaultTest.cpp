// A fault injected mid-run: `driftlab-cli import` killed (SIGKILL, as a power
// cut or the OOM killer would) while it streams a large bundle into a store
// that already holds a campaign. The store must open afterwards, consistent,
// with exactly what it held before; a killed import into a new path must not
// leave a store under that name.
#include <gtest/gtest.h>
#include <QDir>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// Starts an import and kills it once its second pass (the one that writes) is under way.
void killImportWhileItWrites(const QString& bundle, const QString& dbPath) {
    QProcess p;
    p.start(QStringLiteral(DRIFTLAB_CLI),
            {QStringLiteral("import"), bundle, QStringLiteral("--db"), dbPath});
    p.setReadChannel(QProcess::StandardError);  // progress is on stderr
    QByteArray err;
    auto writing = [&] {
        const qsizetype at = err.indexOf("importing:");
        return at >= 0 && err.indexOf(" 10%", at) > at;
    };
    while (!writing()) {
        const bool more = p.waitForReadyRead(60'000);
        err += p.readAllStandardError();
        ASSERT_TRUE(more) << "the import ended before it could be killed: " << err.constData();
    }
    p.kill();
    ASSERT_TRUE(p.waitForFinished(10'000));
    ASSERT_EQ(p.exitStatus(), QProcess::CrashExit);
}

QString bigBundle(const QTemporaryDir& dir) {
    const QString bundle = dir.filePath(QStringLiteral("big"));
    // 400 000 sample times × 8 columns: long enough an import to kill it while it writes.
    EXPECT_FALSE(bundle::writeBundle(generatedCampaign(400'000, 3), bundle));
    return bundle;
}

}  // namespace

TEST(ImportFault, killedImportLeavesTheStoreConsistentWithWhatItHeld) {
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), dbPath})
            .exitCode,
        0);
    killImportWhileItWrites(bigBundle(dir), dbPath);

    QString error;
    auto store = db::CampaignStore::open(dbPath, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA integrity_check")) && q.next());
    EXPECT_EQ(q.value(0).toString(), QStringLiteral("ok"));
    const auto campaigns = store->listCampaigns();
    ASSERT_EQ(campaigns.size(), 1u) << "the killed import left a campaign behind";
    EXPECT_EQ(campaigns[0].name, QStringLiteral("X axis moving-state example"));
    ASSERT_TRUE(q.exec(QStringLiteral("SELECT count(*) FROM sample_block b JOIN run r ON "
                                      "b.run_id = r.id WHERE r.campaign_id <> 1")) &&
                q.next());
    EXPECT_EQ(q.value(0).toInt(), 0) << "sample blocks of the killed import survived";
}

TEST(ImportFault, killedImportIntoANewPathLeavesNoStoreThere) {
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("new.sqlite"));
    killImportWhileItWrites(bigBundle(dir), dbPath);
    EXPECT_FALSE(QFileInfo::exists(dbPath));
    auto partialStores = [&] {
        return QDir(dir.path())
            .entryList({QStringLiteral(".new.sqlite.*")}, QDir::Files | QDir::Hidden);
    };
    // The killed import's partial store (hidden, never published) is still there...
    EXPECT_FALSE(partialStores().isEmpty());
    // The next import of the same bundle works and is not taken for a repeat.
    CliResult again =
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), dbPath});
    EXPECT_EQ(again.exitCode, 0) << again.err.constData();
    EXPECT_EQ(again.out.trimmed(), QByteArray("1"));
    // ...until the next import into that path sweeps it: its process is gone.
    EXPECT_TRUE(partialStores().isEmpty()) << qPrintable(partialStores().join(' '));
}
