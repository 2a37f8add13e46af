// Sensor flags in the store (schema v5): a run's findings stored as ranges and
// read back by run name, replaced when the run is checked again, gone with
// the run; a v4 store migrates to v5 with its data, and a v4 store read
// without migrating has no flags (rather than an error); a v6 store migrates
// to v7, where a flagged stretch the user keeps is used by the models.
#include <gtest/gtest.h>
#include <QSqlQuery>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "db/CampaignStore.h"
#include "db/FlaggedSampleMask.h"
#include "db/SampleFlagStore.h"
#include "db/SchemaMigrations.h"
#include "tests/db/StoreTestSupport.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;
using namespace driftlab::test;
using driftlab::db::CampaignStore;

namespace {

std::unique_ptr<CampaignStore> newStore(const QString& path) {
    QString error;
    auto created = CampaignStore::open(path, db::StoreAccess::CreateIfMissing, &error);
    EXPECT_TRUE(created && created->publish(&error)) << qPrintable(error);
    created.reset();
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    EXPECT_TRUE(store) << qPrintable(error);
    return store;
}

/// The example campaign with T_bearing_fixed of run S1 shorted (−50 °C, the
/// module's clamp) on rows 20…25.
Campaign campaignWithShortedSensor() {
    bundle::BundleReadResult r = bundle::readBundle(exampleBundlePath());
    EXPECT_TRUE(r.ok());
    Campaign c = *r.campaign;
    SampleSeries& s = c.runs.front().samples;
    EXPECT_EQ(c.runs.front().id, QStringLiteral("S1"));
    const int column = s.columnIndex(QStringLiteral("T_bearing_fixed"));
    EXPECT_GE(column, 0);
    for (std::size_t i = 20; i <= 25; ++i) s.values[std::size_t(column)][i] = -50;
    return c;
}

qint64 count(CampaignStore& store, const QString& sql) {
    QSqlQuery q(store.database());
    EXPECT_TRUE(q.exec(sql) && q.next()) << qPrintable(sql);
    return q.value(0).toLongLong();
}

}  // namespace

TEST(SampleFlagStore, aRunsFindingsAreStoredAndReadBackByRunName) {
    QTemporaryDir dir;
    auto store = newStore(dir.filePath(QStringLiteral("lab.sqlite")));
    const Campaign campaign = campaignWithShortedSensor();
    QString error;
    const auto campaignId = store->importCampaign(campaign, &error);
    ASSERT_TRUE(campaignId) << qPrintable(error);
    const auto s1 = db::runDbId(*store, *campaignId, QStringLiteral("S1"), &error);
    ASSERT_TRUE(s1) << qPrintable(error);

    const auto ranges = db::flagRun(*store, *s1, {}, &error);
    ASSERT_TRUE(ranges) << qPrintable(error);
    const std::vector<double>& t = campaign.runs.front().samples.time_s;
    ASSERT_EQ(ranges->size(), 1u);
    EXPECT_EQ(ranges->front(),
              (sensors::FlaggedRange{QStringLiteral("T_bearing_fixed"),
                                     sensors::SensorFault::OutOfRange, t[20], t[25]}));
    auto flags = db::loadSampleFlags(*store, *campaignId, &error);
    ASSERT_TRUE(flags) << qPrintable(error);
    ASSERT_EQ(flags->size(), 1u);
    EXPECT_EQ(flags->at(QStringLiteral("S1")), *ranges);

    // Checked again (as by a second `health --store`): replaced, not added.
    ASSERT_TRUE(db::flagRun(*store, *s1, {}, &error)) << qPrintable(error);
    EXPECT_EQ(count(*store, QStringLiteral("SELECT count(*) FROM sample_flag")), 1);
    // Replaced by nothing: the run has no flags.
    ASSERT_TRUE(db::replaceRunFlags(*store, *s1, {}, &error)) << qPrintable(error);
    flags = db::loadSampleFlags(*store, *campaignId, &error);
    ASSERT_TRUE(flags);
    EXPECT_TRUE(flags->empty());

    EXPECT_FALSE(db::flagRun(*store, 999, {}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no run with id 999"))) << qPrintable(error);
    EXPECT_FALSE(db::runDbId(*store, *campaignId, QStringLiteral("S9"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("'S9'"))) << qPrintable(error);
}

TEST(SampleFlagStore, flagsGoWithTheirRunAndCampaign) {
    QTemporaryDir dir;
    auto store = newStore(dir.filePath(QStringLiteral("lab.sqlite")));
    QString error;
    const auto campaignId = store->importCampaign(campaignWithShortedSensor(), &error);
    ASSERT_TRUE(campaignId) << qPrintable(error);
    for (const QString& run : {QStringLiteral("S1"), QStringLiteral("SP1")}) {
        const auto id = db::runDbId(*store, *campaignId, run, &error);
        ASSERT_TRUE(id) << qPrintable(error);
        ASSERT_TRUE(db::replaceRunFlags(
            *store, *id, {{QStringLiteral("T_nut"), sensors::SensorFault::Spike, 10, 10}}, &error))
            << qPrintable(error);
    }
    EXPECT_EQ(count(*store, QStringLiteral("SELECT count(*) FROM sample_flag")), 2);
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("DELETE FROM run WHERE name = 'S1'")));
    auto flags = db::loadSampleFlags(*store, *campaignId, &error);
    ASSERT_TRUE(flags);
    EXPECT_EQ(flags->size(), 1u);
    EXPECT_TRUE(flags->count(QStringLiteral("SP1")));
    ASSERT_TRUE(q.exec(QStringLiteral("DELETE FROM campaign")));
    EXPECT_EQ(count(*store, QStringLiteral("SELECT count(*) FROM sample_flag")), 0);
}

TEST(SampleFlagStore, aV4StoreMigratesToV5AndReadOnlyItSimplyHasNoFlags) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v4.sqlite"));
    QString error;
    {
        auto store = newStore(path);
        ASSERT_TRUE(store->importCampaign(campaignWithShortedSensor(), &error))
            << qPrintable(error);
    }
    // As a build of schema v4 left it: no sample_flag table (nor the later
    // upload tables), user_version 4.
    rawSql(path,
           {QStringLiteral("DROP TABLE sample_flag"), QStringLiteral("DROP TABLE upload_spool"),
            QStringLiteral("DROP TABLE upload_origin"), QStringLiteral("PRAGMA user_version = 4"),
            QStringLiteral("PRAGMA journal_mode = DELETE")});
    {
        auto readOnly = CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(readOnly) << qPrintable(error);
        EXPECT_EQ(db::schemaVersion(readOnly->database()), 4);
        const auto flags = db::loadSampleFlags(*readOnly, 1, &error);
        ASSERT_TRUE(flags) << qPrintable(error);
        EXPECT_TRUE(flags->empty());
        EXPECT_FALSE(db::replaceRunFlags(*readOnly, 1, {}, &error));
        EXPECT_TRUE(error.contains(QStringLiteral("read-only"))) << qPrintable(error);
    }
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    // Migrated to the latest schema: v5 brought the flags, later ones keep them.
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    EXPECT_GE(db::latestSchemaVersion(), 5);
    const auto campaign = store->loadCampaign(1, &error);
    ASSERT_TRUE(campaign) << qPrintable(error);
    EXPECT_EQ(campaign->runs.size(), 2u);
    const auto s1 = db::runDbId(*store, 1, QStringLiteral("S1"), &error);
    ASSERT_TRUE(s1) << qPrintable(error);
    const auto ranges = db::flagRun(*store, *s1, {}, &error);
    ASSERT_TRUE(ranges) << qPrintable(error);
    EXPECT_EQ(ranges->size(), 1u);
    // The kinds are the health check's ids; the schema refuses others.
    QSqlQuery q(store->database());
    EXPECT_FALSE(q.exec(
        QStringLiteral(
            "INSERT INTO sample_flag (run_id, channel, kind, from_t, to_t) VALUES (%1, 'T_nut', "
            "'bad_luck', 0, 1)")
            .arg(*s1)));
}

TEST(SampleFlagStore, aV6StoreMigratesToV7AndAKeptStretchIsUsedUntilMaskedAgain) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v6.sqlite"));
    QString error;
    const Campaign shorted = campaignWithShortedSensor();
    {
        auto store = newStore(path);
        const auto id = store->importCampaign(shorted, &error);
        ASSERT_TRUE(id) << qPrintable(error);
        const auto s1 = db::runDbId(*store, *id, QStringLiteral("S1"), &error);
        ASSERT_TRUE(s1 && db::flagRun(*store, *s1, {}, &error)) << qPrintable(error);
    }
    // As a build of schema v6 left it: the flag stored, no keep choice.
    rawSql(path, {QStringLiteral("ALTER TABLE sample_flag DROP COLUMN kept"),
                  QStringLiteral("PRAGMA user_version = 6"),
                  QStringLiteral("PRAGMA journal_mode = DELETE")});
    const auto leftOut = [&](CampaignStore& store) {
        Campaign c = shorted;
        const auto masked = db::leaveOutFlaggedSamples(store, 1, c, &error);
        EXPECT_TRUE(masked) << qPrintable(error);
        return masked.value_or(db::MaskedSamples{});
    };
    {
        auto readOnly = CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(readOnly) << qPrintable(error);
        EXPECT_EQ(db::schemaVersion(readOnly->database()), 6);
        const auto flags = db::loadStoredFlags(*readOnly, 1, &error);
        ASSERT_TRUE(flags) << qPrintable(error);
        ASSERT_EQ(flags->at(QStringLiteral("S1")).size(), 1u);
        EXPECT_FALSE(flags->at(QStringLiteral("S1")).front().kept);
        EXPECT_EQ(leftOut(*readOnly).samples, 6u);
        EXPECT_FALSE(db::setFlagsKept(*readOnly, {flags->at(QStringLiteral("S1")).front().id}, true,
                                      &error));
        EXPECT_TRUE(error.contains(QStringLiteral("read-only"))) << qPrintable(error);
    }
    auto store = CampaignStore::open(path, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    EXPECT_EQ(db::schemaVersion(store->database()), db::latestSchemaVersion());
    EXPECT_GE(db::latestSchemaVersion(), 7);
    const qint64 flag = db::loadStoredFlags(*store, 1, &error)->at(QStringLiteral("S1")).front().id;
    EXPECT_EQ(leftOut(*store).samples, 6u);  // an old flag is left out, as before

    ASSERT_TRUE(db::setFlagsKept(*store, {flag}, true, &error)) << qPrintable(error);
    db::MaskedSamples masked = leftOut(*store);
    EXPECT_EQ(masked.samples, 0u);
    EXPECT_EQ(masked.kept, 1u);
    EXPECT_TRUE(masked.describe().contains(QStringLiteral("1 flagged stretch(es) kept")));
    // Checked again, the same stretch is found again and stays kept.
    const auto s1 = db::runDbId(*store, 1, QStringLiteral("S1"), &error);
    ASSERT_TRUE(s1 && db::flagRun(*store, *s1, {}, &error)) << qPrintable(error);
    const db::StoredFlag again =
        db::loadStoredFlags(*store, 1, &error)->at(QStringLiteral("S1")).front();
    EXPECT_TRUE(again.kept);

    ASSERT_TRUE(db::setFlagsKept(*store, {again.id}, false, &error)) << qPrintable(error);
    masked = leftOut(*store);
    EXPECT_EQ(masked.samples, 6u);
    EXPECT_EQ(masked.kept, 0u);
    EXPECT_TRUE(masked.describe().contains(QStringLiteral("T_bearing_fixed out_of_range")))
        << qPrintable(masked.describe());
    // An unknown flag changes nothing and is named.
    EXPECT_FALSE(db::setFlagsKept(*store, {again.id, 9999}, true, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("sensor flag 9999"))) << qPrintable(error);
    EXPECT_FALSE(db::loadStoredFlags(*store, 1, &error)->at(QStringLiteral("S1")).front().kept);
}
