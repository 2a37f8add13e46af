// A database written by schema v1 opens and migrates in this build.
#include <gtest/gtest.h>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "db/CampaignStore.h"
#include "db/SchemaMigrations.h"
#include "tests/core/BundleTestSupport.h"

using namespace driftlab;
using driftlab::db::CampaignStore;

namespace {

/// Writes a v1 database the way a build of schema v1 did: only migration 1,
/// rows inserted with plain SQL (no code of this build's store involved).
void writeSchemaV1Database(const QString& path) {
    QSqlDatabase db =
        QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("v1-writer"));
    db.setDatabaseName(path);
    ASSERT_TRUE(db.open());
    QString error;
    ASSERT_TRUE(db::migrate(db, &error, 1)) << qPrintable(error);
    ASSERT_EQ(db::schemaVersion(db), 1);
    QSqlQuery q(db);
    for (const char* sql :
         {"INSERT INTO campaign (id, name, nut_length_mm, travel_from_mm, travel_to_mm) "
          "VALUES (1, 'legacy campaign', 80, 0, 700)",
          "INSERT INTO machine VALUES (1, 'VMC-850', 'X', 'generic-modbus', '{}')",
          "INSERT INTO screw VALUES (1, 900, 40, 10, -40, 'fixed-free', 1.15e-05, 7850, 460, 45, "
          "'{}')",
          "INSERT INTO channel VALUES (1, 1, 'T_nut', 'temperature', 'nut', 'nut flank', NULL, 0, "
          "0, '{}')",
          "INSERT INTO run VALUES (1, 1, 'S1', 0, 'moving', 8000, 210, 490, 'legacy run', '{}')",
          "INSERT INTO sample VALUES (1, 0, 1, 20.0), (1, 1, 1, 20.5)",
          "INSERT INTO positioning VALUES (1, 0, 0, 350, '+', 1.5)"}) {
        ASSERT_TRUE(q.exec(QString::fromLatin1(sql)))
            << sql << " " << qPrintable(q.lastError().text());
    }
    db.close();
    db = QSqlDatabase();
    QSqlDatabase::removeDatabase(QStringLiteral("v1-writer"));
}

}  // namespace

TEST(SchemaMigration, aSchemaV1DatabaseOpensMigratedWithItsDataIntact) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v1.sqlite"));
    writeSchemaV1Database(path);

    QString error;
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());

    auto campaign = store->loadCampaign(1, &error);
    ASSERT_TRUE(campaign) << qPrintable(error);
    EXPECT_EQ(campaign->name, QStringLiteral("legacy campaign"));
    ASSERT_EQ(campaign->runs.size(), 1u);
    EXPECT_EQ(campaign->runs[0].samples.time_s, (std::vector<double>{0, 1}));
    EXPECT_EQ(campaign->runs[0].samples.values[0], (std::vector<double>{20.0, 20.5}));
    EXPECT_EQ(campaign->runs[0].positioning.size(), 1u);

    // What v2 added is there and usable on the old rows.
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("SELECT status FROM run WHERE id = 1")) && q.next());
    EXPECT_EQ(q.value(0).toString(), QStringLiteral("complete"));
    EXPECT_TRUE(
        q.exec(QStringLiteral("INSERT INTO model_fit (campaign_id, model, train_runs_json, "
                              "test_runs_json, parameters_json, metrics_json) "
                              "VALUES (1, 'mlr', '[\"S1\"]', '[]', '{}', '{}')")))
        << qPrintable(q.lastError().text());
}

TEST(SchemaMigration, aDatabaseFromANewerBuildIsRefusedNotDamaged) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("future.sqlite"));
    {
        QString error;
        auto store = CampaignStore::open(path, db::StoreAccess::CreateIfMissing, &error);
        ASSERT_TRUE(store);
        ASSERT_TRUE(QSqlQuery(store->database()).exec(QStringLiteral("PRAGMA user_version = 99")));
        ASSERT_TRUE(store->publish(&error)) << qPrintable(error);
    }
    const QByteArray before = test::sha256OfFile(path);
    for (auto access : {db::StoreAccess::ReadWrite, db::StoreAccess::ReadOnly}) {
        QString error;
        EXPECT_FALSE(CampaignStore::open(path, access, &error));
        EXPECT_EQ(error, path + QStringLiteral(": database schema v99 is newer than this build "
                                               "(v%1); update DriftLab")
                                    .arg(db::latestSchemaVersion()));
    }
    EXPECT_EQ(test::sha256OfFile(path), before);
}
