// The store never writes into a file that is not its own, reads with
// read-only connections that leave nothing behind, and creates a new store
// only once it is complete (docs/store.md).
#include <gtest/gtest.h>
#include <QElapsedTimer>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "core/bundle/BundleWriter.h"
#include "db/CampaignImport.h"
#include "db/CampaignStore.h"
#include "db/SchemaMigrations.h"
#include "tests/db/StoreTestSupport.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;
using driftlab::db::CampaignStore;
using driftlab::db::StoreAccess;

namespace {

constexpr StoreAccess kEveryAccess[] = {StoreAccess::ReadOnly, StoreAccess::ReadWrite,
                                        StoreAccess::CreateIfMissing};

/// A published store at `path` holding the example campaign (id 1).
void writeExampleStore(const QString& path) {
    QString error;
    auto store = CampaignStore::open(path, StoreAccess::CreateIfMissing, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    ASSERT_TRUE(store->importCampaign(exampleCampaign(), &error)) << qPrintable(error);
    ASSERT_TRUE(store->publish(&error)) << qPrintable(error);
}

qint64 applicationIdOf(CampaignStore& store) {
    QSqlQuery q(store.database());
    return q.exec(QStringLiteral("PRAGMA application_id")) && q.next() ? q.value(0).toLongLong()
                                                                       : -1;
}

}  // namespace

TEST(StoreSafety, applicationIdIsSetOnNewStore) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    QString error;
    auto store = CampaignStore::open(path, StoreAccess::CreateIfMissing, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_TRUE(store->isNew());
    EXPECT_EQ(store->path(), path);
    EXPECT_EQ(applicationIdOf(*store), qint64(db::kStoreApplicationId));
    EXPECT_FALSE(QFile::exists(path)) << "a new store appears only when published";
    ASSERT_TRUE(store->publish(&error)) << qPrintable(error);
    store.reset();

    EXPECT_EQ(headerApplicationId(path), db::kStoreApplicationId);
    EXPECT_EQ(header(path).mid(68, 4), QByteArray("DRFT"));
    EXPECT_EQ(headerJournalVersion(path), 1) << "at rest a store is in rollback-journal mode";
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("lab.sqlite")});
}

TEST(StoreSafety, legacyStoreWithoutApplicationIdIsAcceptedAndStamped) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("legacy.sqlite"));
    writeExampleStore(path);
    makeLegacyStore(path);
    ASSERT_EQ(headerApplicationId(path), 0u);
    ASSERT_EQ(headerJournalVersion(path), 2);
    const QByteArray before = sha256OfFile(path);
    QString error;
    {
        // Read as it is: a read-only open stamps nothing.
        auto store = CampaignStore::open(path, StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        EXPECT_TRUE(store->loadCampaign(1, &error)) << qPrintable(error);
    }
    EXPECT_EQ(sha256OfFile(path), before);
    EXPECT_EQ(headerApplicationId(path), 0u);
    {
        auto store = CampaignStore::open(path, StoreAccess::ReadWrite, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        EXPECT_EQ(applicationIdOf(*store), qint64(db::kStoreApplicationId));
        EXPECT_EQ(store->listCampaigns().size(), 1u);
    }
    EXPECT_EQ(headerApplicationId(path), db::kStoreApplicationId);
    EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
}

TEST(StoreSafety, importIntoAnotherApplicationsDatabaseIsRefusedAndLeavesItByteIdentical) {
    QTemporaryDir dir;
    const QString notes = dir.filePath(QStringLiteral("notes.sqlite"));
    writeForeignDatabase(notes, 0, {QStringLiteral("notes")});
    const QString geo = dir.filePath(QStringLiteral("map.gpkg"));
    const QStringList gpkgTables{"gpkg_contents",         "gpkg_extensions",
                                 "gpkg_geometry_columns", "gpkg_ogr_contents",
                                 "gpkg_spatial_ref_sys",  "rivers"};
    writeForeignDatabase(geo, 0x47504B47, gpkgTables);  // a GeoPackage: 'GPKG'
    const QString never =
        QStringLiteral("; DriftLab never writes into another application's database");
    const struct {
        QString path, why;
    } cases[] = {
        {notes, QStringLiteral("not a DriftLab store (application_id 0x00000000, tables: notes)")},
        {geo, QStringLiteral("not a DriftLab store (application_id 0x47504b47, tables: "
                             "gpkg_contents, gpkg_extensions, gpkg_geometry_columns, "
                             "gpkg_ogr_contents, gpkg_spatial_ref_sys, …)")},
    };
    for (const auto& c : cases) {
        const QByteArray before = sha256OfFile(c.path);
        for (StoreAccess access : kEveryAccess) {
            QString error;
            EXPECT_FALSE(CampaignStore::open(c.path, access, &error));
            EXPECT_EQ(error, c.path + QStringLiteral(": ") + c.why +
                                 (access == StoreAccess::ReadOnly ? QString() : never));
        }
        EXPECT_EQ(sha256OfFile(c.path), before);
        EXPECT_TRUE(sideFiles(c.path).isEmpty()) << qPrintable(sideFiles(c.path).join(' '));
    }
}

TEST(StoreSafety, importIntoNonSqliteFileIsRefused) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("notes.sqlite"));
    writeFile(path, QByteArray("these are my notes, not a database\n").repeated(100));
    const QByteArray before = sha256OfFile(path);
    for (StoreAccess access : kEveryAccess) {
        QString error;
        EXPECT_FALSE(CampaignStore::open(path, access, &error));
        EXPECT_EQ(error, path + QStringLiteral(": not an SQLite database"));
    }
    EXPECT_EQ(sha256OfFile(path), before);
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("notes.sqlite")});
}

TEST(StoreSafety, infoOnMissingStoreIsAnErrorAndCreatesNothing) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("typo.sqlite"));
    for (StoreAccess access : {StoreAccess::ReadOnly, StoreAccess::ReadWrite}) {
        QString error;
        EXPECT_FALSE(CampaignStore::open(path, access, &error));
        EXPECT_EQ(error, path + QStringLiteral(": no such DriftLab store"));
    }
    EXPECT_TRUE(folderEntries(dir.path()).isEmpty())
        << qPrintable(folderEntries(dir.path()).join(' '));
}

TEST(StoreSafety, refusedImportIntoNewPathLeavesNoFile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("new.sqlite"));
    Campaign bad = exampleCampaign();
    bad.screw->diameter_mm = 0;  // refused by the schema's CHECK, inside the import
    QString error;
    {
        auto store = CampaignStore::open(path, StoreAccess::CreateIfMissing, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        EXPECT_FALSE(store->importCampaign(bad, &error));
        EXPECT_TRUE(error.contains(QStringLiteral("CHECK constraint failed"))) << qPrintable(error);
    }
    EXPECT_TRUE(folderEntries(dir.path()).isEmpty())
        << qPrintable(folderEntries(dir.path()).join(' '));
}

TEST(StoreSafety, publishNeverReplacesAFileThatAppearedMeanwhile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    QString error;
    auto store = CampaignStore::open(path, StoreAccess::CreateIfMissing, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    ASSERT_TRUE(store->importCampaign(exampleCampaign(), &error)) << qPrintable(error);
    writeFile(path, "someone else's\n");
    EXPECT_FALSE(store->publish(&error));
    EXPECT_EQ(error,
              path + QStringLiteral(": a file appeared there meanwhile; nothing was stored"));
    EXPECT_EQ(readFile(path), QByteArray("someone else's\n"));
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("lab.sqlite")});
}

TEST(StoreSafety, readOnlyCommandsLeaveNoWalOrShm) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    writeExampleStore(path);
    const QByteArray before = sha256OfFile(path);
    QString error;
    {
        auto store = CampaignStore::open(path, StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        EXPECT_EQ(store->loadCampaign(1, &error), exampleCampaign()) << qPrintable(error);
        EXPECT_EQ(store->listCampaigns().size(), 1u);
        EXPECT_FALSE(QSqlQuery(store->database()).exec(QStringLiteral("DELETE FROM campaign")))
            << "a read-only store refuses writes";
    }
    EXPECT_EQ(sha256OfFile(path), before);
    EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
}

TEST(StoreSafety, aReaderWhileAWriterIsOpenSeesWhatItCommits) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    writeExampleStore(path);
    QString error;
    auto writer = CampaignStore::open(path, StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(writer) << qPrintable(error);
    auto reader = CampaignStore::open(path, StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reader) << qPrintable(error);
    EXPECT_EQ(reader->listCampaigns().size(), 1u);
    ASSERT_TRUE(writer->importCampaign(exampleCampaign(), &error)) << qPrintable(error);
    EXPECT_EQ(reader->listCampaigns().size(), 2u);
    // The writer closes first: the open reader keeps the store in WAL mode.
    writer.reset();
    EXPECT_EQ(reader->listCampaigns().size(), 2u);
    reader.reset();
    // The next writer to close alone leaves it at rest again.
    ASSERT_TRUE(CampaignStore::open(path, StoreAccess::ReadWrite, &error)) << qPrintable(error);
    EXPECT_EQ(headerJournalVersion(path), 1);
    EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
}

TEST(StoreSafety, aReadOnlyOpenNeverMigrates) {
    QTemporaryDir dir;
    // Schema v3, the oldest a reader reads (samples in blocks): read as it is.
    const QString v3 = dir.filePath(QStringLiteral("v3.sqlite"));
    {
        QString error;
        auto store = CampaignStore::open(v3, StoreAccess::CreateIfMissing, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        ASSERT_TRUE(store->importCampaign(exampleCampaign(), &error)) << qPrintable(error);
        ASSERT_TRUE(store->publish(&error)) << qPrintable(error);
    }
    rawSql(v3, {QStringLiteral("PRAGMA user_version = 3")});
    const QByteArray before = sha256OfFile(v3);
    QString error;
    {
        auto store = CampaignStore::open(v3, StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(store) << qPrintable(error);
        EXPECT_EQ(db::schemaVersion(store->database()), 3);
        EXPECT_TRUE(store->loadCampaign(1, &error)) << qPrintable(error);
    }
    EXPECT_EQ(sha256OfFile(v3), before);

    // Schema v2 (samples a row per value): a reader does not migrate it.
    rawSql(v3, {QStringLiteral("PRAGMA user_version = 2")});
    EXPECT_FALSE(CampaignStore::open(v3, StoreAccess::ReadOnly, &error));
    EXPECT_EQ(error, v3 + QStringLiteral(
                              ": store schema v2 is older; open it once for writing to migrate"));

    // Schema v0 with DriftLab's mark: nothing to read until migrated.
    const QString v0 = dir.filePath(QStringLiteral("v0.sqlite"));
    rawSql(v0, {QStringLiteral("PRAGMA application_id = %1").arg(db::kStoreApplicationId)});
    EXPECT_FALSE(CampaignStore::open(v0, StoreAccess::ReadOnly, &error));
    EXPECT_EQ(error, v0 + QStringLiteral(
                              ": store schema v0 is older; open it once for writing to migrate"));
    auto migrated = CampaignStore::open(v0, StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(migrated) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(migrated->database()), db::latestSchemaVersion());
}

TEST(StoreSafety, aStoreLockedByAnotherProcessIsWaitedForThenNamedAsInUse) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    writeExampleStore(path);
    const QByteArray before = sha256OfFile(path);
    const QString inUse = path + QStringLiteral(
                                     ": in use by another process (it kept the store locked for "
                                     "more than 5 s); the store is unchanged");
    {
        // The switch into WAL mode, which SQLite does not wait for by itself.
        const HeldStoreLock held(path, QStringLiteral("BEGIN IMMEDIATE"));
        ASSERT_TRUE(held.locked);
        QElapsedTimer waited;
        waited.start();
        QString error;
        EXPECT_FALSE(CampaignStore::open(path, StoreAccess::ReadWrite, &error));
        EXPECT_GE(waited.elapsed(), db::kStoreBusyTimeout_ms - 100) << "the busy timeout applies";
        EXPECT_EQ(error, inUse);
    }
    EXPECT_EQ(sha256OfFile(path), before);

    // A lock taken once the store is open: the import's transaction waits as long.
    QString error;
    auto store = CampaignStore::open(path, StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto source = bundle::openBundleFolder(exampleBundlePath(), &error);
    const db::BundleCheck checked = db::checkBundle(*source);
    ASSERT_TRUE(checked.ok()) << qPrintable(checked.error);
    {
        const HeldStoreLock held(path, QStringLiteral("BEGIN IMMEDIATE"));
        ASSERT_TRUE(held.locked);
        db::BundleImportOptions again;
        again.again = true;
        const db::BundleImportResult result = db::importBundle(*store, *source, checked, again);
        EXPECT_FALSE(result.campaignId);
        EXPECT_EQ(result.error,
                  path + QStringLiteral(": in use by another process (it kept the store locked "
                                        "for more than 5 s): nothing of 'X axis moving-state "
                                        "example' was imported; the store is unchanged"));
    }
    EXPECT_EQ(store->listCampaigns().size(), 1u);
}

TEST(StoreSafety, anImportThatFillsTheDiskSaysSoAndLeavesTheStoreAsItWas) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    writeExampleStore(path);
    const QString bundle = dir.filePath(QStringLiteral("big"));
    ASSERT_FALSE(bundle::writeBundle(generatedCampaign(20'000), bundle));
    QString error;
    const auto source = bundle::openBundleFolder(bundle, &error);
    const db::BundleCheck checked = db::checkBundle(*source);
    ASSERT_TRUE(checked.ok()) << qPrintable(checked.error);

    auto store = CampaignStore::open(path, StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    // SQLite's own stand-in for a full disk: the file may grow by two pages only.
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA page_count")) && q.next());
    ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA max_page_count = %1").arg(q.value(0).toInt() + 2)));
    const db::BundleImportResult result = db::importBundle(*store, *source, checked);
    EXPECT_FALSE(result.campaignId);
    EXPECT_EQ(result.error, path + QStringLiteral(": disk full: nothing of '%1' was imported; the "
                                                  "store is unchanged")
                                       .arg(checked.name));
    store.reset();

    auto reopened = CampaignStore::open(path, StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reopened) << qPrintable(error);
    const auto campaigns = reopened->listCampaigns();
    ASSERT_EQ(campaigns.size(), 1u);
    EXPECT_EQ(campaigns[0].name, QStringLiteral("X axis moving-state example"));
}
