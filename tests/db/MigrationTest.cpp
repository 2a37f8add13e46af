// A database written by schema v1 opens and migrates in this build.
#include <gtest/gtest.h>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <cmath>

#include "core/bundle/BundleReader.h"
#include "db/CampaignStore.h"
#include "db/PushHistory.h"
#include "db/SchemaMigrations.h"
#include "tests/support/BundleTestSupport.h"

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

// Schema v3 moved samples from a row per value into blocks: the whole example
// campaign, stored as v2 stored it (rows written here with plain SQL, missing
// samples without a row), comes back value for value after the migration.
TEST(SchemaMigration, aSchemaV2StoreKeepsEverySampleWhenItsRowsMoveIntoBlocks) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v2.sqlite"));
    bundle::BundleReadResult example = bundle::readBundle(test::exampleBundlePath());
    ASSERT_TRUE(example.ok());
    const Campaign& c = *example.campaign;
    {
        QSqlDatabase db =
            QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("v2-writer"));
        db.setDatabaseName(path);
        ASSERT_TRUE(db.open());
        QString error;
        ASSERT_TRUE(db::migrate(db, &error, 2)) << qPrintable(error);
        QSqlQuery q(db);
        ASSERT_TRUE(db.transaction());
        ASSERT_TRUE(q.exec(QStringLiteral(
            "INSERT INTO campaign (id, name, nut_length_mm, travel_from_mm, travel_to_mm) "
            "VALUES (1, 'v2 campaign', 80, 0, 700)")));
        ASSERT_TRUE(q.exec(QStringLiteral("INSERT INTO machine VALUES (1, 'm', 'X', '', '{}')")));
        // Channels in column order; ids 1.. are the column ordinals + 1.
        for (std::size_t k = 0; k < c.sample_columns.size(); ++k)
            ASSERT_TRUE(q.exec(QStringLiteral("INSERT INTO channel (id, campaign_id, name, "
                                              "quantity, declared_ordinal, column_ordinal) VALUES "
                                              "(%1, 1, '%2', 'temperature', %3, %3)")
                                   .arg(k + 1)
                                   .arg(c.sample_columns[k])
                                   .arg(k)))
                << qPrintable(q.lastError().text());
        q.prepare(QStringLiteral("INSERT INTO sample VALUES (?, ?, ?, ?)"));
        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            ASSERT_TRUE(QSqlQuery(db).exec(
                QStringLiteral("INSERT INTO run (id, campaign_id, name, ordinal, kind) VALUES "
                               "(%1, 1, '%2', %3, 'moving')")
                    .arg(r + 1)
                    .arg(c.runs[r].id)
                    .arg(r)));
            const SampleSeries& s = c.runs[r].samples;
            for (std::size_t i = 0; i < s.rowCount(); ++i)
                for (std::size_t k = 0; k < s.values.size(); ++k) {
                    if (std::isnan(s.values[k][i])) continue;
                    q.addBindValue(qint64(r + 1));
                    q.addBindValue(s.time_s[i]);
                    q.addBindValue(qint64(k + 1));
                    q.addBindValue(s.values[k][i]);
                    ASSERT_TRUE(q.exec()) << qPrintable(q.lastError().text());
                }
        }
        ASSERT_TRUE(db.commit());
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("v2-writer"));
    }

    QString error;
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    auto migrated = store->loadCampaign(1, &error);
    ASSERT_TRUE(migrated) << qPrintable(error);
    ASSERT_EQ(migrated->runs.size(), c.runs.size());
    for (std::size_t r = 0; r < c.runs.size(); ++r)
        EXPECT_EQ(migrated->runs[r].samples, c.runs[r].samples) << qPrintable(c.runs[r].id);
    QSqlQuery gone(store->database());
    EXPECT_FALSE(gone.exec(QStringLiteral("SELECT count(*) FROM sample")))
        << "the per-value table is dropped";
}

// Schema v4 replaced v2's compensation_push (a push hung on a stored table row)
// by the push history; a v3 store's pushes come through with what they knew.
TEST(SchemaMigration, aSchemaV3StoreKeepsItsPushesInTheV4History) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v3.sqlite"));
    {
        QSqlDatabase db =
            QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("v3-writer"));
        db.setDatabaseName(path);
        ASSERT_TRUE(db.open());
        QString error;
        ASSERT_TRUE(db::migrate(db, &error, 3)) << qPrintable(error);
        QSqlQuery q(db);
        for (const char* sql :
             {"INSERT INTO campaign (id, name, nut_length_mm, travel_from_mm, travel_to_mm) "
              "VALUES (1, 'v3 campaign', 80, 0, 700)",
              "INSERT INTO compensation_table (id, campaign_id, axis, start_mm, spacing_mm, "
              "values_um_json) VALUES (5, 1, 'X', 0, 350, '[-1.5,0.25,2]')",
              "INSERT INTO compensation_push (id, table_id, target, outcome, message, pushed_at) "
              "VALUES (1, 5, 'modbus://plc:502', 'rolled_back', 'read-back mismatch', "
              "'2024-05-01T10:00:00.000Z')"})
            ASSERT_TRUE(q.exec(QString::fromLatin1(sql)))
                << sql << " " << qPrintable(q.lastError().text());
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("v3-writer"));
    }
    QString error;
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    auto pushes = db::pushHistory(*store, 1, &error);
    ASSERT_TRUE(pushes) << qPrintable(error);
    ASSERT_EQ(pushes->size(), 1u);
    const db::PushRecord& old = pushes->front();
    EXPECT_EQ(old.pushed_at, QStringLiteral("2024-05-01T10:00:00.000Z"));
    EXPECT_EQ(old.campaign_id, std::optional<qint64>(1));
    EXPECT_EQ(old.controller_url, QStringLiteral("modbus://plc:502"));
    EXPECT_EQ(old.result, QStringLiteral("rolled_back"));
    EXPECT_EQ(old.message, QStringLiteral("read-back mismatch"));
    EXPECT_EQ(old.points, 3);
    EXPECT_EQ(old.table[QStringLiteral("spacing_mm")].toDouble(), 350);
    EXPECT_EQ(old.table[QStringLiteral("correction_um")].toArray().at(1).toDouble(), 0.25);

    // A push from a bundle folder has no campaign in the store.
    db::PushRecord fromBundle;
    fromBundle.controller_url = QStringLiteral("modbus://127.0.0.1:1502");
    fromBundle.result = QStringLiteral("applied");
    fromBundle.points = 21;
    ASSERT_TRUE(db::storePush(*store, fromBundle, &error)) << qPrintable(error);
    pushes = db::pushHistory(*store, std::nullopt, &error);
    ASSERT_TRUE(pushes) << qPrintable(error);
    ASSERT_EQ(pushes->size(), 2u);
    EXPECT_FALSE(pushes->back().campaign_id);
    EXPECT_TRUE(pushes->back().pushed_at.endsWith(QLatin1Char('Z')));
}
