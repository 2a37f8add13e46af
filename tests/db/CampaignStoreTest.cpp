// The SQLite campaign store: lossless round trips, one transaction per import.
#include <gtest/gtest.h>
#include <QCoreApplication>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"
#include "db/SchemaMigrations.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;
using driftlab::db::CampaignStore;

namespace {

/// The store at `path` opened for writing; created (empty) first if missing.
std::unique_ptr<CampaignStore> openStore(const QString& path) {
    QString error;
    if (auto created = CampaignStore::open(path, db::StoreAccess::CreateIfMissing, &error);
        created && created->isNew()) {
        EXPECT_TRUE(created->publish(&error)) << qPrintable(error);
    }
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    EXPECT_TRUE(store) << qPrintable(error);
    return store;
}

/// A store file without the two header fields SQLite bumps when a connection
/// switches the journal mode (file change counter at offset 24, version-valid-for
/// at 92): a store opened for writing rests in rollback mode again when closed,
/// so these change even when nothing is stored. Every page is compared.
QByteArray withoutChangeCounter(QByteArray bytes) {
    for (int offset : {24, 92}) bytes.replace(offset, 4, QByteArray(4, '\0'));
    return bytes;
}

}  // namespace

TEST(CampaignStore, newDatabaseIsWalWithForeignKeysAtTheLatestSchema) {
    QTemporaryDir dir;
    auto store = openStore(dir.filePath(QStringLiteral("lab.sqlite")));
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA journal_mode")) && q.next());
    EXPECT_EQ(q.value(0).toString(), QStringLiteral("wal"));
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA foreign_keys")) && q.next());
    EXPECT_EQ(q.value(0).toInt(), 1);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    EXPECT_GE(db::latestSchemaVersion(), 2);
}

TEST(CampaignStore, importThenLoadGivesTheBundleBackExactly) {
    QTemporaryDir dir;
    const Campaign original = exampleCampaign();
    auto store = openStore(dir.filePath(QStringLiteral("lab.sqlite")));
    QString error;
    auto id = store->importCampaign(original, &error);
    ASSERT_TRUE(id) << qPrintable(error);
    auto loaded = store->loadCampaign(*id, &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(*loaded, original);

    auto list = store->listCampaigns();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].name, original.name);
    EXPECT_EQ(list[0].runs, 2);
    qint64 present = 0;
    for (const auto& run : original.runs) present += qint64(run.samples.presentValueCount());
    EXPECT_EQ(list[0].samples, present);
}

TEST(CampaignStore, importExportImportIsLossless) {
    QTemporaryDir dir;
    auto store = openStore(dir.filePath(QStringLiteral("lab.sqlite")));
    QString error;
    auto first = store->importCampaign(exampleCampaign(), &error);
    ASSERT_TRUE(first);
    auto loaded = store->loadCampaign(*first, &error);
    ASSERT_TRUE(loaded);
    ASSERT_FALSE(bundle::writeBundle(*loaded, dir.filePath(QStringLiteral("exported"))));

    bundle::BundleReadResult exported =
        bundle::readBundle(dir.filePath(QStringLiteral("exported")));
    ASSERT_TRUE(exported.ok()) << qPrintable(exported.error->toString());
    auto second = store->importCampaign(*exported.campaign, &error);
    ASSERT_TRUE(second);
    EXPECT_NE(*first, *second);
    auto reloaded = store->loadCampaign(*second, &error);
    ASSERT_TRUE(reloaded);
    EXPECT_EQ(*reloaded, *loaded);
    // The bundle files themselves are identical too.
    ASSERT_FALSE(bundle::writeBundle(*reloaded, dir.filePath(QStringLiteral("exported2"))));
    for (const char* name : {"campaign.json", "samples.csv", "motion.csv", "positioning.csv"})
        EXPECT_EQ(sha256OfFile(dir.filePath(QStringLiteral("exported/") + QLatin1String(name))),
                  sha256OfFile(dir.filePath(QStringLiteral("exported2/") + QLatin1String(name))))
            << name;
}

TEST(CampaignStore, failedImportRollsBackAndLeavesTheFileUnchangedButItsChangeCounter) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    QString error;
    openStore(path)->importCampaign(exampleCampaign(), &error);
    const QByteArray before = withoutChangeCounter(readFile(path));

    // A screw that the schema's CHECK refuses fails after the campaign row is written.
    Campaign bad = exampleCampaign();
    bad.name = QStringLiteral("bad screw");
    bad.screw->diameter_mm = 0;
    {
        auto store = openStore(path);
        EXPECT_FALSE(store->importCampaign(bad, &error));
        EXPECT_TRUE(error.contains(QStringLiteral("rolled back"))) << qPrintable(error);
        EXPECT_TRUE(error.contains(QStringLiteral("CHECK constraint failed"))) << qPrintable(error);
        EXPECT_EQ(store->listCampaigns().size(), 1u);
    }
    EXPECT_EQ(withoutChangeCounter(readFile(path)), before);
}

TEST(CampaignStore, cancelledImportStoresNothing) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    auto store = openStore(path);
    QString error;
    auto id =
        store->importCampaign(generatedCampaign(100'000), &error, [](double f) { return f < 0.5; });
    EXPECT_FALSE(id);
    EXPECT_TRUE(error.contains(QStringLiteral("import cancelled"))) << qPrintable(error);
    EXPECT_TRUE(store->listCampaigns().empty());
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("SELECT count(*) FROM sample_block")) && q.next());
    EXPECT_EQ(q.value(0).toInt(), 0);
}

TEST(CampaignStore, importsAMillionSampleBundle) {
    QTemporaryDir dir;
    // 125,000 sample times x 8 columns = one million sample values.
    const Campaign big = generatedCampaign(125'000, 11);
    ASSERT_FALSE(bundle::writeBundle(big, dir.filePath(QStringLiteral("big"))));
    bundle::BundleReadResult read = bundle::readBundle(dir.filePath(QStringLiteral("big")));
    ASSERT_TRUE(read.ok()) << qPrintable(read.error->toString());

    auto store = openStore(dir.filePath(QStringLiteral("lab.sqlite")));
    QString error;
    auto id = store->importCampaign(*read.campaign, &error);
    ASSERT_TRUE(id) << qPrintable(error);
    auto list = store->listCampaigns();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].samples, 1'000'000);
    auto loaded = store->loadCampaign(*id, &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(*loaded, big);
}

TEST(CampaignStore, aFileThatIsNotADatabaseIsRefusedWithItsName) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("notes.sqlite"));
    writeFile(path, QByteArray("these are my notes, not a database\n").repeated(100));
    QString error;
    EXPECT_FALSE(CampaignStore::open(path, db::StoreAccess::ReadWrite, &error));
    EXPECT_EQ(error, path + QStringLiteral(": not an SQLite database"));
}
