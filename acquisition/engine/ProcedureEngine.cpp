#include "acquisition/engine/ProcedureEngine.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonDocument>
#include <chrono>
#include <cmath>

#include "acquisition/engine/RunPlayback.h"
#include "core/domain/MessageText.h"
#include "db/CampaignStore.h"
#include "db/RunLogger.h"
#include "db/SampleFlagStore.h"

namespace driftlab::engine {
namespace {

qint64 nowMs() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

bool fail(QString* error, const QString& why) {
    if (error) *error = why;
    return false;
}

/// Opens the store for writing, creating it when it does not exist yet.
std::unique_ptr<db::CampaignStore> openStore(const QString& path, QString* error) {
    if (!QFileInfo::exists(path)) {
        auto created = db::CampaignStore::open(path, db::StoreAccess::CreateIfMissing, error);
        if (!created || !created->publish(error)) return nullptr;
    }
    return db::CampaignStore::open(path, db::StoreAccess::ReadWrite, error);
}

db::RunHeader headerOf(const procedures::PlannedRun& run, const procedures::Procedure& p) {
    return {run.id,
            run.kind,
            run.feed_mm_min,
            run.range_mm,
            run.description,
            {{QStringLiteral("procedure"), p.name},
             {QStringLiteral("procedure_kind"), toString(p.kind)}}};
}

/// The sensor self-diagnosis of what was logged, stored with the run: the
/// models leave flagged samples out unless told otherwise.
void flagLoggedRun(db::CampaignStore& store, db::RunLogger& logger) {
    QString why;
    if (!logger.commit(&why)) return;  // the logger reports it again when it finishes
    const auto flagged = db::flagRun(store, logger.runId(), {}, &why);
    QStringList channels;
    for (const auto& range : flagged.value_or(std::vector<sensors::FlaggedRange>{}))
        if (!channels.contains(range.channel)) channels << range.channel;
    logger.appendEvent(flagged ? QStringLiteral("info") : QStringLiteral("warning"),
                       QStringLiteral("sensor health"),
                       !flagged ? QStringLiteral("not checked: %1").arg(why)
                       : channels.isEmpty()
                           ? QStringLiteral("no flagged samples")
                           : QStringLiteral("%1 flagged ranges on %2; models leave them out")
                                 .arg(flagged->size())
                                 .arg(channels.join(QStringLiteral(", "))));
}

/// Why `rig` (its campaign header) is not the rig the resumed run was logged
/// on, or empty. A simulated run is replayed to where its log ends, so its
/// rig must be the same to the seed; a real one must log the same channels
/// of the same machine (its address may change).
QString otherRig(const db::LoggedRunState& run, const TestRig& testRig, const Campaign& rig,
                 const std::vector<QString>& loggedColumns) {
    const bool realTime = testRig.realTime();
    const QString describe = testRig.describe();
    if (run.rig_real_time && *run.rig_real_time != realTime)
        return QStringLiteral("it was logged on %1").arg(run.rig);
    if (!realTime && !run.rig.isEmpty() && run.rig != describe)
        return QStringLiteral("it was logged on %1").arg(run.rig);
    if (!run.machine.isEmpty() && run.machine != rig.machine.name)
        return QStringLiteral("it was logged on machine '%1', this rig is '%2'")
            .arg(run.machine, rig.machine.name);
    if (loggedColumns != rig.sample_columns)
        return QStringLiteral("it logged the columns %1, this rig logs %2")
            .arg(quotedList(QStringList(loggedColumns.begin(), loggedColumns.end())),
                 quotedList(QStringList(rig.sample_columns.begin(), rig.sample_columns.end())));
    return {};
}

}  // namespace

QString toString(EngineState state) {
    switch (state) {
        case EngineState::Idle:
            return QStringLiteral("idle");
        case EngineState::Running:
            return QStringLiteral("running");
        case EngineState::Paused:
            return QStringLiteral("paused");
        case EngineState::Aborting:
            return QStringLiteral("aborting");
        case EngineState::Finished:
            return QStringLiteral("finished");
        case EngineState::Interrupted:
            return QStringLiteral("interrupted");
    }
    return {};
}

ProcedureEngine::ProcedureEngine(procedures::Procedure procedure, TestRig& rig,
                                 EngineOptions options)
    : m_procedure(std::move(procedure)), m_rig(rig), m_options(std::move(options)) {}

void ProcedureEngine::setState(EngineState state) {
    m_state = state;
}

void ProcedureEngine::pause() {
    m_pauseRequested = true;
    m_wake.notify_all();
}
void ProcedureEngine::resume() {
    m_pauseRequested = false;
    m_wake.notify_all();
}
void ProcedureEngine::abort() {
    m_abortRequested = true;
    m_wake.notify_all();
}

bool ProcedureEngine::stopping() const {
    return m_abortRequested || (m_options.stop_requested && m_options.stop_requested->load());
}

bool ProcedureEngine::waitWhilePaused() {
    if (!m_pauseRequested || stopping()) return !stopping();
    setState(EngineState::Paused);
    std::unique_lock lock(m_mutex);
    while (m_pauseRequested && !stopping()) {
        if (m_rig.realTime() && QCoreApplication::instance()) {
            // Device signals arrive through this thread's event loop.
            lock.unlock();
            QCoreApplication::processEvents();
            lock.lock();
        }
        m_wake.wait_for(lock, std::chrono::milliseconds(20));
    }
    if (stopping()) return false;
    setState(EngineState::Running);
    return true;
}

bool ProcedureEngine::waitUntil(qint64 wall_ms) {
    std::unique_lock lock(m_mutex);
    for (qint64 now = nowMs(); now < wall_ms; now = nowMs()) {
        if (stopping() || m_pauseRequested) break;
        if (m_rig.realTime() && QCoreApplication::instance()) {
            lock.unlock();
            QCoreApplication::processEvents();
            lock.lock();
        }
        m_wake.wait_for(lock, std::chrono::milliseconds(std::min<qint64>(wall_ms - now, 20)));
    }
    return !stopping();
}

bool ProcedureEngine::waitForDevices(RunSource& source) {
    std::unique_lock lock(m_mutex);
    while (source.deviceLost() && !stopping() && source.failure().isEmpty()) {
        lock.unlock();
        if (QCoreApplication::instance()) QCoreApplication::processEvents();
        lock.lock();
        m_wake.wait_for(lock, std::chrono::milliseconds(20));
    }
    return !stopping();
}

std::optional<qint64> ProcedureEngine::run(QString* error) {
    std::vector<procedures::PlannedRun> planned;
    try {
        planned = procedures::planRuns(m_procedure);
    } catch (const std::exception& e) {
        fail(error, QStringLiteral("procedure %1: %2").arg(m_procedure.name, e.what()));
        return std::nullopt;
    }
    auto store = openStore(m_options.store_path, error);
    if (!store) return std::nullopt;
    QString why;
    db::markInterruptedRuns(*store, &why);

    qint64 campaignId = 0;
    std::size_t first = 0;
    std::optional<db::LoggedRunState> resumed;
    if (m_options.resume_run_id) {
        resumed = db::loggedRunState(*store, *m_options.resume_run_id, error);
        if (!resumed) return std::nullopt;
        if (resumed->status != QLatin1String("interrupted")) {
            fail(error, QStringLiteral("run %1 (%2) is %3, not interrupted: nothing to resume")
                            .arg(resumed->run_id)
                            .arg(resumed->name, resumed->status));
            return std::nullopt;
        }
        campaignId = resumed->campaign_id;
        while (first < planned.size() && planned[first].id != resumed->name) ++first;
        if (first == planned.size()) {
            fail(error, QStringLiteral("run %1 (%2) is not a run of procedure '%3'")
                            .arg(resumed->run_id)
                            .arg(resumed->name, m_procedure.name));
            return std::nullopt;
        }
        if (const QString why = otherRig(*resumed, m_rig, m_rig.campaignHeader(planned),
                                         db::sampleColumns(*store, campaignId));
            !why.isEmpty()) {
            fail(error, QStringLiteral("run %1 (%2) cannot be resumed on %3: %4")
                            .arg(resumed->run_id)
                            .arg(resumed->name, m_rig.describe(), why));
            return std::nullopt;
        }
    } else {
        Campaign header = m_rig.campaignHeader(planned);
        header.name = m_procedure.name;
        header.extra[QStringLiteral("procedure")] = procedures::toJson(m_procedure);
        header.extra[QStringLiteral("rig")] = m_rig.describe();
        header.extra[QStringLiteral("rig_real_time")] = m_rig.realTime();
        const auto id = store->importCampaign(header, error);
        if (!id) return std::nullopt;
        campaignId = *id;
    }
    const std::vector<QString> columns = db::sampleColumns(*store, campaignId);

    setState(EngineState::Running);
    for (std::size_t i = first; i < planned.size(); ++i) {
        const bool resuming = resumed && i == first;
        auto logger = resuming ? db::RunLogger::resume(*store, resumed->run_id, error)
                               : db::RunLogger::begin(*store, campaignId,
                                                      headerOf(planned[i], m_procedure), error);
        if (!logger) {
            setState(EngineState::Interrupted);
            return std::nullopt;
        }
        RunPlayback playback{planned[i], i, planned.size(), *logger, columns};
        if (resuming) playback.resumeFrom(*resumed, m_rig.realTime());
        const bool ok = playRun(playback, error);
        flagLoggedRun(*store, *logger);
        if (!ok || stopping()) {
            if (stopping())
                logger->appendEvent(
                    QStringLiteral("warning"), QStringLiteral("engine"),
                    QStringLiteral("aborted by the operator at %1 s").arg(playback.time_s));
            const bool marked = logger->finish(QStringLiteral("interrupted"), ok ? error : nullptr);
            if (!ok && !marked && error)
                *error += QStringLiteral(
                    "; the run is marked interrupted when the store is next "
                    "opened");
            setState(EngineState::Interrupted);
            if (!ok) return std::nullopt;
            return campaignId;
        }
        if (!logger->finish(QStringLiteral("complete"), error)) {
            setState(EngineState::Interrupted);
            return std::nullopt;
        }
    }
    setState(EngineState::Finished);
    return campaignId;
}

}  // namespace driftlab::engine

namespace driftlab::engine {

bool ProcedureEngine::playRun(RunPlayback& pb, QString* error) {
    auto source = m_rig.open(pb.run, pb.index, pb.columns, error);
    if (!source) return false;
    if (m_observers.run_started) m_observers.run_started(pb.index, pb.run.id, pb.columns);
    const double step_s = m_procedure.sample_interval_s;
    rig::RunOutput out;
    // The wall clock paces the run from (wallStart, runStart); re-based after a pause.
    qint64 wallStart = nowMs();
    double runStart_s = pb.time_s;
    const double replayUntil_s = m_rig.realTime() ? -1 : pb.time_s;
    QString storeProblem;
    // Each retry writes every row held so far: a store that keeps refusing
    // is retried less and less often, up to every 30 s.
    int commitInterval_ms = m_options.commit_interval_ms;
    auto report = [&] {
        if (m_progress)
            m_progress({pb.run.id, pb.index, pb.count, pb.time_s, pb.run.duration_s, state(),
                        storeProblem, pb.logger.savedUntil_s().value_or(0)});
    };
    report();
    // After a pause a simulated run goes on where it stopped; a real one at
    // the time it is now (run time stays wall time; the pause is a gap).
    auto afterPause = [&] {
        if (m_rig.realTime()) {
            const double elapsed_s = (nowMs() - wallStart) / 1000.0;
            pb.time_s = std::max(pb.time_s, runStart_s + std::floor(elapsed_s / step_s) * step_s);
        } else {
            wallStart = nowMs();
            runStart_s = pb.time_s;
        }
    };
    auto logSourceEvents = [&] {
        std::vector<SourceEvent> events = source->takeEvents();
        // A simulated run replayed to where its log ends has logged these already.
        if (!m_rig.realTime() && pb.replaying()) return;
        for (const SourceEvent& e : events) {
            pb.logger.appendEvent(e.level, e.source, e.message);
            if (m_observers.device_event) m_observers.device_event(e);
        }
    };
    while (!source->finished()) {
        if (m_pauseRequested) {
            const double pausedAt_s = pb.time_s;
            report();
            if (!waitWhilePaused()) return true;
            pb.logger.appendEvent(QStringLiteral("info"), QStringLiteral("engine"),
                                  QStringLiteral("paused by the operator at %1 s").arg(pausedAt_s));
            afterPause();
        }
        if (m_procedure.on_device_loss == procedures::DeviceLossPolicy::Pause &&
            source->deviceLost()) {
            logSourceEvents();
            pb.logger.appendEvent(QStringLiteral("warning"), QStringLiteral("engine"),
                                  QStringLiteral("paused at %1 s: a device stopped answering "
                                                 "(on_device_loss: pause)")
                                      .arg(pb.time_s));
            setState(EngineState::Paused);
            report();
            if (!waitForDevices(*source)) return true;
            setState(EngineState::Running);
            afterPause();
        }
        if (stopping()) return true;
        if (const QString failure = source->failure(); !failure.isEmpty()) {
            logSourceEvents();
            pb.logger.appendEvent(QStringLiteral("error"), QStringLiteral("engine"), failure);
            return fail(error, failure);
        }
        const double next_s = pb.time_s + step_s;
        const bool paced = m_rig.realTime() || m_options.speedup > 0;
        if (paced && next_s > replayUntil_s) {
            const double rate = m_rig.realTime() ? 1.0 : m_options.speedup;
            if (!waitUntil(wallStart + qint64((next_s - runStart_s) / rate * 1000.0))) return true;
            if (m_pauseRequested) continue;
        }
        out.clear();
        source->advanceTo(next_s, out);
        pb.time_s = next_s;
        if (auto note = pb.checkStabilisation(out)) {
            source->replan(pb.run);
            pb.logger.appendEvent(QStringLiteral("info"), QStringLiteral("iso230-3"), *note);
        }
        pb.log(out, m_rows, m_observers.reading);
        pb.logMotionUntil(pb.time_s);
        logSourceEvents();
        QString why;
        if (pb.logger.commitIfDue(&why, commitInterval_ms)) {
            commitInterval_ms = m_options.commit_interval_ms;
            if (!storeProblem.isEmpty())
                pb.logger.appendEvent(QStringLiteral("warning"), QStringLiteral("logger"),
                                      QStringLiteral("the store took the rows again at %1 s "
                                                     "after refusing them: %2")
                                          .arg(pb.time_s)
                                          .arg(storeProblem));
            storeProblem.clear();
        } else {
            // A full disk is the operator's to fix: the rows stay in memory and
            // every commit is retried, until memory would run out.
            storeProblem = why;
            commitInterval_ms = std::min(2 * commitInterval_ms, 30'000);
            if (pb.logger.unsavedRows() > m_options.max_unsaved_rows)
                return fail(error,
                            QStringLiteral("%1; the store refused rows for too long: run %2 from "
                                           "%3 s to %4 s (%5 rows) could not be saved and is "
                                           "lost")
                                .arg(why, pb.run.id)
                                .arg(numberText(pb.logger.savedUntil_s().value_or(0)),
                                     numberText(pb.time_s))
                                .arg(pb.logger.unsavedRows()));
        }
        report();
    }
    pb.logMotionUntil(std::numeric_limits<double>::max());
    // The run's last rows are kept as long as the operator may free space:
    // until the store takes them or the run is stopped.
    for (QString why; !pb.logger.commit(&why);) {
        storeProblem = why;
        report();
        if (!waitUntil(nowMs() + m_options.commit_interval_ms)) break;
    }
    if (!storeProblem.isEmpty()) {
        storeProblem.clear();
        report();
    }
    return true;
}

}  // namespace driftlab::engine
