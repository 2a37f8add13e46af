// The store on both back ends: the same tests on a SQLite file and on a
// database of the test cluster (PgTestServer.h), and what only a server
// store must do (its mark, refusing a foreign database, read-only sessions).
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "db/CampaignImport.h"
#include "db/CampaignStore.h"
#include "db/SampleFlagStore.h"
#include "db/SchemaMigrations.h"
#include "db/StoreBackend.h"
#include "db/ZipBundleSource.h"
#include "tests/postgres/PgTestServer.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;
using driftlab::db::CampaignStore;
using driftlab::db::StoreAccess;

namespace driftlab::db {
// The back end by name in test lists, not as bytes.
void PrintTo(StoreBackend backend, std::ostream* os) {
    *os << (backend == StoreBackend::Postgres ? "postgres" : "sqlite");
}
}  // namespace driftlab::db

namespace {

qint64 count(CampaignStore& store, const QString& table) {
    QSqlQuery q(store.database());
    EXPECT_TRUE(q.exec(QStringLiteral("SELECT count(*) FROM ") + table));
    return q.next() ? q.value(0).toLongLong() : -1;
}

std::string backendName(const ::testing::TestParamInfo<db::StoreBackend>& info) {
    return info.param == db::StoreBackend::Postgres ? "postgres" : "sqlite";
}

}  // namespace

// The fixture is outside the anonymous namespace: its tests derive from it.
/// A new empty store location of one back end: a file in a temporary folder,
/// or a fresh database on the test cluster.
class BothBackEnds : public ::testing::TestWithParam<db::StoreBackend> {
protected:
    void SetUp() override {
        if (GetParam() == db::StoreBackend::Postgres) {
            DRIFTLAB_REQUIRE_PG_CLUSTER();
            m_location = PgTestServer::freshDatabase(QStringLiteral("store_test"));
        } else {
            m_location = m_dir.filePath(QStringLiteral("lab.sqlite"));
        }
    }
    /// The store, created when missing, opened for writing.
    std::unique_ptr<CampaignStore> openForWriting() {
        QString error;
        if (auto created = CampaignStore::open(m_location, StoreAccess::CreateIfMissing, &error);
            created && created->isNew()) {
            EXPECT_TRUE(created->publish(&error)) << qPrintable(error);
        }
        auto store = CampaignStore::open(m_location, StoreAccess::ReadWrite, &error);
        EXPECT_TRUE(store) << qPrintable(error);
        return store;
    }

    QTemporaryDir m_dir;
    QString m_location;
};

TEST_P(BothBackEnds, importThenLoadGivesTheCampaignBackExactly) {
    const Campaign original = exampleCampaign();
    auto store = openForWriting();
    ASSERT_TRUE(store);
    EXPECT_EQ(store->isServer(), GetParam() == db::StoreBackend::Postgres);
    QString error;
    auto id = store->importCampaign(original, &error);
    ASSERT_TRUE(id) << qPrintable(error);
    auto loaded = store->loadCampaign(*id, &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(*loaded, original);
    const auto list = store->listCampaigns();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].name, original.name);
    qint64 present = 0;
    for (const auto& run : original.runs) present += qint64(run.samples.presentValueCount());
    EXPECT_EQ(list[0].samples, present);
}

TEST_P(BothBackEnds, manyBlocksWithMissingSamplesRoundTripBitForBit) {
    // 5,000 rows: three blocks per run, NaN (missing) cells, float64 values that
    // a text round trip with too few digits would change.
    const Campaign big = generatedCampaign(5'000, 7);
    auto store = openForWriting();
    ASSERT_TRUE(store);
    QString error;
    auto id = store->importCampaign(big, &error);
    ASSERT_TRUE(id) << qPrintable(error);
    EXPECT_GE(count(*store, QStringLiteral("sample_block")), 3);
    auto loaded = store->loadCampaign(*id, &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(*loaded, big);
}

TEST_P(BothBackEnds, aFailedImportLeavesNothing) {
    auto store = openForWriting();
    ASSERT_TRUE(store);
    // A screw the schema's CHECK refuses: fails after the campaign row is written.
    Campaign bad = generatedCampaign(3'000, 3);
    bad.screw->diameter_mm = 0;
    QString error;
    EXPECT_FALSE(store->importCampaign(bad, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("rolled back"))) << qPrintable(error);
    EXPECT_TRUE(store->listCampaigns().empty());
    for (const char* table : {"campaign", "channel", "run", "sample_block", "positioning"})
        EXPECT_EQ(count(*store, QLatin1String(table)), 0) << table;
}

TEST_P(BothBackEnds, aBadBundleImportsNothing) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("bad"));
    copyBundle(exampleBundlePath(), bundle);
    // Time going backwards in the last lines: found after many rows were stored.
    QByteArray samples = readFile(bundle + QStringLiteral("/samples.csv"));
    samples += "S1,1.0,20,20,20,20,20";
    writeFile(bundle + QStringLiteral("/samples.csv"), samples + '\n');
    auto store = openForWriting();
    ASSERT_TRUE(store);
    QString error;
    auto source = db::openBundleSource(bundle, &error);
    ASSERT_TRUE(source) << qPrintable(error);
    // Checked or not, the import itself refuses it in its one transaction.
    const db::BundleCheck unchecked{{}, QStringLiteral("bad"), {}, QByteArray("0")};
    const auto result = db::importBundle(*store, *source, unchecked);
    EXPECT_FALSE(result.campaignId);
    EXPECT_TRUE(result.error.contains(QStringLiteral("samples.csv"))) << qPrintable(result.error);
    EXPECT_TRUE(store->listCampaigns().empty());
    EXPECT_EQ(count(*store, QStringLiteral("sample_block")), 0);
}

TEST_P(BothBackEnds, aKeptFlagStaysKeptAcrossConnectionsAndAReCheck) {
    auto store = openForWriting();
    ASSERT_TRUE(store);
    QString error;
    const auto id = store->importCampaign(exampleCampaign(), &error);
    ASSERT_TRUE(id) << qPrintable(error);
    const auto s1 = db::runDbId(*store, *id, QStringLiteral("S1"), &error);
    ASSERT_TRUE(s1) << qPrintable(error);
    const std::vector<sensors::FlaggedRange> ranges{
        {QStringLiteral("T_nut"), sensors::SensorFault::Spike, 10, 10},
        {QStringLiteral("T_nut"), sensors::SensorFault::Frozen, 100, 200}};
    ASSERT_TRUE(db::replaceRunFlags(*store, *s1, ranges, &error)) << qPrintable(error);
    const auto stored = [&] {
        auto reader = CampaignStore::open(m_location, StoreAccess::ReadOnly, &error);
        EXPECT_TRUE(reader) << qPrintable(error);
        const auto flags = db::loadStoredFlags(*reader, *id, &error);
        EXPECT_TRUE(flags) << qPrintable(error);
        return flags->at(QStringLiteral("S1"));
    };
    ASSERT_EQ(stored().size(), 2u);
    EXPECT_FALSE(stored()[0].kept || stored()[1].kept);  // every flag is left out at first
    ASSERT_TRUE(db::setFlagsKept(*store, {stored()[1].id}, true, &error)) << qPrintable(error);
    EXPECT_FALSE(stored()[0].kept);
    EXPECT_TRUE(stored()[1].kept);
    // Found again by a re-check: the choice stays with its stretch.
    ASSERT_TRUE(db::replaceRunFlags(*store, *s1, ranges, &error)) << qPrintable(error);
    EXPECT_FALSE(stored()[0].kept);
    EXPECT_TRUE(stored()[1].kept);
    ASSERT_TRUE(db::setFlagsKept(*store, {stored()[1].id}, false, &error)) << qPrintable(error);
    EXPECT_FALSE(stored()[1].kept);
}

TEST_P(BothBackEnds, migrationsGiveTheSameSchemaVersion) {
    EXPECT_EQ(db::latestSchemaVersion(db::StoreBackend::Postgres),
              db::latestSchemaVersion(db::StoreBackend::Sqlite));
    auto store = openForWriting();
    ASSERT_TRUE(store);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    // Opening again migrates nothing and keeps the version.
    store.reset();
    QString error;
    auto reader = CampaignStore::open(m_location, StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reader) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(reader->database()), db::latestSchemaVersion());
    // Both have the same tables (the server store adds its mark).
    QStringList tables = reader->database().tables();
    tables.removeAll(QStringLiteral("driftlab_store"));
    tables.removeAll(QStringLiteral("sqlite_sequence"));
    tables.sort();
    EXPECT_EQ(tables,
              (QStringList{"campaign", "channel", "compensation_push", "compensation_table",
                           "diagnosis", "event_log", "interferometer", "machine", "model_fit",
                           "motion_segment", "positioning", "run", "sample_block", "sample_flag",
                           "screw", "upload_origin", "upload_spool"}));
}

INSTANTIATE_TEST_SUITE_P(Store, BothBackEnds,
                         ::testing::Values(db::StoreBackend::Sqlite, db::StoreBackend::Postgres),
                         backendName);

TEST(ServerStore, aForeignDatabaseIsRefusedAndLeftUntouched) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("someone_elses"));
    PgTestServer::rawSql(QStringLiteral("someone_elses"),
                         {QStringLiteral("CREATE TABLE invoice (id serial PRIMARY KEY, total "
                                         "numeric)"),
                          QStringLiteral("INSERT INTO invoice (total) VALUES (42)")});
    for (StoreAccess access :
         {StoreAccess::ReadOnly, StoreAccess::ReadWrite, StoreAccess::CreateIfMissing}) {
        QString error;
        EXPECT_FALSE(CampaignStore::open(url, access, &error));
        EXPECT_TRUE(error.contains(QStringLiteral("not a DriftLab store"))) << qPrintable(error);
        EXPECT_TRUE(error.contains(QStringLiteral("invoice"))) << qPrintable(error);
    }
    // Nothing was added: the only table is still the invoices.
    PgTestServer::rawSql(
        QStringLiteral("someone_elses"),
        {QStringLiteral("DO $$ BEGIN IF (SELECT count(*) FROM information_schema.tables WHERE "
                        "table_schema = 'public') <> 1 THEN RAISE EXCEPTION 'tables added'; "
                        "END IF; END $$")});
}

TEST(ServerStore, anEmptyDatabaseIsNotReadAsAStoreButBecomesOneWhenWritten) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("empty_one"));
    QString error;
    EXPECT_FALSE(CampaignStore::open(url, StoreAccess::ReadOnly, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no DriftLab store"))) << qPrintable(error);
    auto store = CampaignStore::open(url, StoreAccess::CreateIfMissing, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_FALSE(store->isNew());
    EXPECT_TRUE(store->publish(&error)) << qPrintable(error);
    auto reader = CampaignStore::open(url, StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reader) << qPrintable(error);
    QSqlQuery q(reader->database());
    ASSERT_TRUE(q.exec(QStringLiteral("SELECT application_id FROM driftlab_store")) && q.next());
    EXPECT_EQ(q.value(0).toLongLong(), qint64(db::kStoreApplicationId));
}

TEST(ServerStore, aReadOnlyStoreRefusesWrites) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("read_only"));
    QString error;
    ASSERT_TRUE(CampaignStore::open(url, StoreAccess::ReadWrite, &error)) << qPrintable(error);
    auto reader = CampaignStore::open(url, StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(reader) << qPrintable(error);
    EXPECT_FALSE(reader->importCampaign(exampleCampaign(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("read-only"))) << qPrintable(error);
}

TEST(ServerStore, anUnreachableServerIsAOneLineErrorNamingTheUrl) {
    QString error;
    // Port 1 on the loopback: nothing listens, the connection is refused at once.
    EXPECT_FALSE(CampaignStore::open(QStringLiteral("postgresql://driftlab:secret@127.0.0.1:1/lab"),
                                     StoreAccess::ReadOnly, &error));
    EXPECT_TRUE(
        error.startsWith(QStringLiteral("postgresql://driftlab@127.0.0.1:1/lab: cannot "
                                        "connect")))
        << qPrintable(error);
    EXPECT_FALSE(error.contains(QStringLiteral("secret")));
    EXPECT_FALSE(error.contains(QLatin1Char('\n'))) << qPrintable(error);
    EXPECT_FALSE(CampaignStore::open(QStringLiteral("postgresql://127.0.0.1"),
                                     StoreAccess::ReadOnly, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no database name"))) << qPrintable(error);
}
