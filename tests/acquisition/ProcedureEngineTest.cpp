// The procedure engine on the simulated rig, logging into a real SQLite file:
// a logged campaign is the batch simulation's campaign, sample for sample;
// pause, resume and abort at random points lose nothing; an aborted run
// resumed is the run that was never aborted; ISO 230-3 ends its warm-up at
// stabilisation; the simulated module's outage is logged as a device rig
// logs a lost module, once, even when the run is resumed after it.
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QTemporaryDir>
#include <chrono>
#include <random>
#include <thread>

#include "acquisition/engine/ProcedureEngine.h"
#include "acquisition/engine/SimulatedRig.h"
#include "acquisition/live/LiveSampleBuffer.h"
#include "core/rig/CampaignSimulator.h"
#include "db/CampaignStore.h"
#include "db/RunLogger.h"
#include "tests/acquisition/LoggedRunSupport.h"

using namespace driftlab;
using namespace std::chrono_literals;

namespace {

/// The rig the batch simulator runs for the same states.
rig::RigSpec rigFor(const procedures::Procedure& p) {
    rig::RigSpec spec;
    spec.seed = 11;
    spec.travel_mm = p.travel_mm;
    spec.sample_interval_s = p.sample_interval_s;
    spec.runs.clear();
    for (const auto& s : p.moving_states->states)
        spec.runs.push_back({s.run_id, s.feed_mm_min, s.range_mm, s.warmup_s, s.cooldown_s});
    return spec;
}

engine::EngineOptions storeAt(const QString& path) {
    engine::EngineOptions options;
    options.store_path = path;
    return options;
}

Campaign loadOnly(const QString& path, qint64 id) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    auto c = store->loadCampaign(id, &error);
    EXPECT_TRUE(c) << error.toStdString();
    return *c;
}

void expectSameRuns(const Campaign& logged, const Campaign& batch) {
    ASSERT_EQ(logged.runs.size(), batch.runs.size());
    for (std::size_t r = 0; r < batch.runs.size(); ++r) {
        SCOPED_TRACE(batch.runs[r].id.toStdString());
        EXPECT_EQ(logged.runs[r].samples, batch.runs[r].samples);
        EXPECT_EQ(logged.runs[r].positioning, batch.runs[r].positioning);
        EXPECT_EQ(logged.runs[r].motion, batch.runs[r].motion);
    }
}

/// "RUN level source: message" of every event of the store, in logging order.
QStringList eventLog(const QString& path) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    QStringList events;
    if (!store) return events;
    QSqlQuery q(store->database());
    q.exec(
        QStringLiteral("SELECT r.name, e.level, e.source, e.message FROM event_log e "
                       "JOIN run r ON r.id = e.run_id ORDER BY e.id"));
    while (q.next())
        events << q.value(0).toString() + " " + q.value(1).toString() + " " +
                      q.value(2).toString() + ": " + q.value(3).toString();
    return events;
}

/// The two events of S1's module outage from 600 s to 900 s, and no other of the module.
void expectOneOutageLogged(const QStringList& events) {
    const QString log = events.join('\n');
    EXPECT_EQ(events.filter(QStringLiteral("temperature module")),
              QStringList({"S1 error temperature module sim: sim: the module does not answer "
                           "(simulated outage)",
                           "S1 warning temperature module sim: gap: no data from 600 s to 900 s "
                           "(300 s); reconnected"}))
        << log.toStdString();
}

rig::RigSpec withS1Outage(const procedures::Procedure& p) {
    rig::RigSpec spec = rigFor(p);
    spec.module_outages = {{QStringLiteral("S1"), 600, 900}};
    return spec;
}

}  // namespace

TEST(ProcedureEngine, LoggedCampaignIsTheBatchSimulationSampleForSample) {
    QTemporaryDir dir;
    const auto procedure = test::twoShortMovingStates();
    engine::SimulatedRig rig(rigFor(procedure));
    engine::ProcedureEngine engine(procedure, rig, storeAt(dir.filePath("lab.sqlite")));
    QString error;
    const auto id = engine.run(&error);
    ASSERT_TRUE(id) << error.toStdString();
    EXPECT_EQ(engine.state(), engine::EngineState::Finished);
    expectSameRuns(loadOnly(dir.filePath("lab.sqlite"), *id),
                   rig::simulateCampaign(rigFor(procedure)));
    EXPECT_EQ(test::runStatuses(dir.filePath("lab.sqlite")),
              QStringList({"S1=complete", "S2=complete"}));
}

TEST(ProcedureEngine, PauseAndResumeAtRandomPointsLoseNothing) {
    QTemporaryDir dir;
    const auto procedure = test::twoShortMovingStates();
    engine::SimulatedRig rig(rigFor(procedure));
    engine::EngineOptions options = storeAt(dir.filePath("lab.sqlite"));
    options.speedup = 4000;  // 5 h of runs in about 4.5 s
    options.commit_interval_ms = 50;
    engine::ProcedureEngine engine(procedure, rig, options);
    std::optional<qint64> id;
    QString error;
    std::thread worker([&] { id = engine.run(&error); });
    std::mt19937 rng(5);
    int pausesSeen = 0;
    for (int i = 0; i < 6 && engine.state() != engine::EngineState::Finished; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100 + rng() % 400));
        engine.pause();
        std::this_thread::sleep_for(150ms);
        pausesSeen += engine.state() == engine::EngineState::Paused;
        engine.resume();
    }
    worker.join();
    ASSERT_TRUE(id) << error.toStdString();
    EXPECT_GE(pausesSeen, 3);
    EXPECT_EQ(engine.state(), engine::EngineState::Finished);
    expectSameRuns(loadOnly(dir.filePath("lab.sqlite"), *id),
                   rig::simulateCampaign(rigFor(procedure)));
}

TEST(ProcedureEngine, AbortedRunResumedIsTheRunNeverAborted) {
    for (int trial = 0; trial < 3; ++trial) {
        SCOPED_TRACE(trial);
        QTemporaryDir dir;
        const QString path = dir.filePath("lab.sqlite");
        const auto procedure = test::twoShortMovingStates();
        engine::SimulatedRig rig(rigFor(procedure));
        engine::EngineOptions options = storeAt(path);
        options.speedup = 4000;
        engine::ProcedureEngine first(procedure, rig, options);
        std::optional<qint64> id;
        QString error;
        std::thread worker([&] { id = first.run(&error); });
        std::this_thread::sleep_for(std::chrono::milliseconds(200 + 450 * trial));
        first.abort();
        worker.join();
        ASSERT_TRUE(id) << error.toStdString();
        EXPECT_EQ(first.state(), engine::EngineState::Interrupted);
        const QStringList statuses = test::runStatuses(path);
        ASSERT_FALSE(statuses.isEmpty());
        EXPECT_TRUE(statuses.last().endsWith(QLatin1String("=interrupted")))
            << statuses.join(' ').toStdString();

        QString why;
        auto store = db::CampaignStore::open(path, db::StoreAccess::ReadWrite, &why);
        QSqlQuery q(store->database());
        q.exec(QStringLiteral("SELECT id FROM run WHERE status = 'interrupted'"));
        ASSERT_TRUE(q.next());
        options.resume_run_id = q.value(0).toLongLong();
        q.finish();
        store.reset();
        options.speedup = 0;
        engine::ProcedureEngine second(procedure, rig, options);
        const auto resumedId = second.run(&error);
        ASSERT_TRUE(resumedId) << error.toStdString();
        EXPECT_EQ(*resumedId, *id);
        EXPECT_EQ(second.state(), engine::EngineState::Finished);
        expectSameRuns(loadOnly(path, *id), rig::simulateCampaign(rigFor(procedure)));
    }
}

TEST(ProcedureEngine, ResumeRefusesACompleteRunAndAForeignOne) {
    QTemporaryDir dir;
    const QString path = dir.filePath("lab.sqlite");
    const auto procedure = test::twoShortMovingStates();
    engine::SimulatedRig rig(rigFor(procedure));
    QString error;
    ASSERT_TRUE(engine::ProcedureEngine(procedure, rig, storeAt(path)).run(&error));
    engine::EngineOptions options = storeAt(path);
    options.resume_run_id = 1;
    EXPECT_FALSE(engine::ProcedureEngine(procedure, rig, options).run(&error));
    EXPECT_TRUE(error.contains(QLatin1String("complete"))) << error.toStdString();
    options.resume_run_id = 99;
    EXPECT_FALSE(engine::ProcedureEngine(procedure, rig, options).run(&error));
    EXPECT_TRUE(error.contains(QLatin1String("99"))) << error.toStdString();
}

TEST(ProcedureEngine, Iso230_3WarmupEndsWhenTheCriterionHolds) {
    QTemporaryDir dir;
    const QString path = dir.filePath("lab.sqlite");
    procedures::Procedure p;
    p.name = QStringLiteral("ISO 230-3 axis");
    p.kind = procedures::ProcedureKind::Iso230_3Axis;
    procedures::ThermalDistortionSpec t;
    t.stabilisation_um = 2.5;
    t.max_warmup_s = 6 * 3600;
    t.cooldown_s = 1800;
    p.thermal_distortion = t;
    engine::SimulatedRig rig(rigFor(test::twoShortMovingStates()));
    QString error;
    const auto id = engine::ProcedureEngine(p, rig, storeAt(path)).run(&error);
    ASSERT_TRUE(id) << error.toStdString();
    const Campaign c = loadOnly(path, *id);
    ASSERT_EQ(c.runs.size(), 1u);
    const driftlab::Run& run = c.runs.front();
    // It stopped warming well before the six hours and cooled for its 30 min.
    const double end_s = run.samples.time_s.back();
    EXPECT_LT(end_s, 5 * 3600.0);
    const MotionSegment& lastMove =
        *std::find_if(run.motion.rbegin(), run.motion.rend(), [&](const MotionSegment& m) {
            return !m.isDwell() && std::abs(m.feed_mm_min) == t.feed_mm_min;
        });
    EXPECT_GT(end_s - lastMove.end_s, t.cooldown_s);
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    QSqlQuery q(store->database());
    q.exec(QStringLiteral("SELECT message FROM event_log WHERE source = 'iso230-3'"));
    ASSERT_TRUE(q.next());
    EXPECT_TRUE(q.value(0).toString().contains(QLatin1String("stabilised")))
        << q.value(0).toString().toStdString();
}

TEST(ProcedureEngine, LiveReadPathSeesEveryLoggedRowWhileTheRunGoesOn) {
    QTemporaryDir dir;
    auto procedure = test::twoShortMovingStates();
    procedure.moving_states->states.resize(1);
    const rig::RigSpec spec = rigFor(procedure);
    const auto columns = rig::rigCampaignHeader(spec, false).sample_columns;
    live::LiveSampleBuffer buffer(QStringList(columns.begin(), columns.end()));
    engine::SimulatedRig rig(spec);
    engine::EngineOptions options = storeAt(dir.filePath("lab.sqlite"));
    options.speedup = 4000;
    engine::ProcedureEngine engine(procedure, rig, options);
    engine.setRowObserver([&](double t, const double* values, std::size_t count) {
        QString error;
        EXPECT_TRUE(buffer.append(t, {values, count}, &error)) << error.toStdString();
    });
    // A reader on its own thread, as the GUI's plots and the live compensation read.
    std::atomic<bool> done{false};
    SampleSeries seen;
    seen.columns = columns;
    seen.values.assign(columns.size(), {});
    int reads = 0;
    std::thread reader([&] {
        std::int64_t next = 0;
        while (!done || next < buffer.rowCount()) {
            buffer.waitForRows(next + 1, std::chrono::milliseconds(20));
            const live::LiveRows rows = buffer.rowsSince(next);
            reads += !rows.empty();
            for (std::int64_t r = rows.beginRow(); r < rows.endRow(); ++r) {
                seen.time_s.push_back(rows.time_s(r));
                for (int c = 0; c < rows.columns(); ++c)
                    seen.values[std::size_t(c)].push_back(rows.value(r, c));
            }
            next = rows.endRow();
        }
    });
    QString error;
    const auto id = engine.run(&error);
    done = true;
    reader.join();
    ASSERT_TRUE(id) << error.toStdString();
    EXPECT_GT(reads, 10);  // it read while the run went on, not once at the end
    EXPECT_EQ(seen, loadOnly(dir.filePath("lab.sqlite"), *id).runs.front().samples);
}

TEST(ProcedureEngine, ModuleOutageIsLoggedAsADeviceRigLogsALostModule) {
    QTemporaryDir dir;
    const QString path = dir.filePath("lab.sqlite");
    const auto procedure = test::twoShortMovingStates();
    engine::SimulatedRig rig(withS1Outage(procedure));
    QString error;
    const auto id = engine::ProcedureEngine(procedure, rig, storeAt(path)).run(&error);
    ASSERT_TRUE(id) << error.toStdString();
    const Campaign logged = loadOnly(path, *id);
    expectSameRuns(logged, rig::simulateCampaign(withS1Outage(procedure)));
    const SampleSeries& s1 = logged.runs.front().samples;
    const auto& nut = s1.values[std::size_t(s1.columnIndex(QStringLiteral("T_nut")))];
    const auto& position = s1.values[std::size_t(s1.columnIndex(kPositionColumn))];
    int missing = 0;
    for (std::size_t r = 0; r < s1.rowCount(); ++r) {
        const bool lost = s1.time_s[r] >= 600 && s1.time_s[r] < 900;
        EXPECT_EQ(std::isnan(nut[r]), lost) << s1.time_s[r];
        EXPECT_FALSE(std::isnan(position[r])) << s1.time_s[r];
        missing += lost;
    }
    EXPECT_EQ(missing, 30);
    expectOneOutageLogged(eventLog(path));
    EXPECT_EQ(test::runStatuses(path), QStringList({"S1=complete", "S2=complete"}));
}

TEST(ProcedureEngine, ModuleOutageIsLoggedOnceWhenTheRunIsResumedAfterIt) {
    QTemporaryDir dir;
    const QString path = dir.filePath("lab.sqlite");
    const auto procedure = test::twoShortMovingStates();
    engine::SimulatedRig rig(withS1Outage(procedure));
    engine::EngineOptions options = storeAt(path);
    engine::ProcedureEngine first(procedure, rig, options);
    first.setProgressCallback([&](const engine::EngineProgress& p) {
        if (p.time_s >= 1500) first.abort();
    });
    QString error;
    const auto id = first.run(&error);
    ASSERT_TRUE(id) << error.toStdString();
    ASSERT_EQ(test::runStatuses(path), QStringList({"S1=interrupted"}));
    options.resume_run_id = 1;
    engine::ProcedureEngine second(procedure, rig, options);
    ASSERT_TRUE(second.run(&error)) << error.toStdString();
    expectSameRuns(loadOnly(path, *id), rig::simulateCampaign(withS1Outage(procedure)));
    expectOneOutageLogged(eventLog(path));
}
