#pragma once
// The procedure engine (docs/acquisition.md): plays a procedure's runs on a
// rig and logs everything into the store through db::RunLogger. A state
// machine — idle, running, paused, aborting, finished, interrupted — whose
// pause(), resume() and abort() may be called from any thread; run() blocks
// the thread it is called on (the CLI's, or an acquisition thread of the
// GUI), which must not be the GUI thread.
//
// Nothing logged is lost: rows are committed at least every second; pause
// stops the run's clock (on a real rig the gap is recorded); abort commits
// what was logged and marks the run interrupted, so `run --resume` can
// continue it. A resumed simulated run is replayed silently to where its log
// ends (the rig is deterministic per seed), then logged on.

#include <QString>
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>

#include "acquisition/engine/TestRig.h"
#include "core/procedures/Procedure.h"

namespace driftlab::engine {

struct RunPlayback;

enum class EngineState { Idle, Running, Paused, Aborting, Finished, Interrupted };
QString toString(EngineState state);

struct EngineOptions {
    QString store_path;
    /// Run time per wall-clock time on a simulated rig; 0 = as fast as it goes.
    double speedup = 0;
    /// The id (in the store) of an interrupted run to continue.
    std::optional<qint64> resume_run_id;
    int commit_interval_ms = 1000;
    /// Rows held in memory while the store refuses them (a full disk): the
    /// run goes on and commits are retried until the operator frees space;
    /// beyond this many the run fails, naming what is lost.
    qint64 max_unsaved_rows = 1'000'000;
    /// Set from elsewhere (a signal handler: it may only store an atomic) to
    /// stop the run as abort() does; read at every step and in every wait.
    const std::atomic<bool>* stop_requested = nullptr;
};

struct EngineProgress {
    QString run;
    std::size_t run_index = 0;
    std::size_t run_count = 0;
    double time_s = 0;
    double duration_s = 0;
    EngineState state = EngineState::Idle;
    /// Why the store refuses the rows (empty when it takes them), and since
    /// what run time they are held in memory only.
    QString store_problem;
    double unsaved_since_s = 0;
};

/// A logged row, for the live read path: run time and the campaign's columns.
using RowObserver = std::function<void(double time_s, const double* values, std::size_t count)>;
/// A logged interferometer reading, for the live dashboard.
using ReadingObserver = std::function<void(const PositioningMeasurement&)>;

/// What a GUI watches besides the rows, called on the engine's thread: a run
/// starting (before its first row; its columns are the row's values), each
/// interferometer reading and each device event as they are logged.
struct EngineObservers {
    std::function<void(std::size_t index, const QString& run, const std::vector<QString>& columns)>
        run_started;
    ReadingObserver reading;
    std::function<void(const SourceEvent&)> device_event;
};

class ProcedureEngine {
public:
    ProcedureEngine(procedures::Procedure procedure, TestRig& rig, EngineOptions options);

    /// Runs the procedure (or continues the resumed run and the runs after
    /// it); returns the campaign id, or nullopt with `error`. An abort is not
    /// an error: the id is returned and state() is Interrupted.
    std::optional<qint64> run(QString* error);

    void pause();
    void resume();
    void abort();
    EngineState state() const { return m_state.load(); }

    void setProgressCallback(std::function<void(const EngineProgress&)> callback) {
        m_progress = std::move(callback);
    }
    void setRowObserver(RowObserver observer) { m_rows = std::move(observer); }
    /// Set before run(); the observers must be thread-safe towards their readers.
    void setObservers(EngineObservers observers) { m_observers = std::move(observers); }

private:
    bool playRun(RunPlayback& playback, QString* error);
    /// Waits until `wall_ms` (steady clock) while running; returns false on abort.
    bool waitUntil(qint64 wall_ms);
    /// Blocks while a device of `source` is lost (policy pause) and the source
    /// has not failed; false on abort.
    bool waitForDevices(RunSource& source);
    /// Blocks while paused; false on abort.
    bool waitWhilePaused();
    void setState(EngineState state);
    /// abort() called or the stop flag set.
    bool stopping() const;

    procedures::Procedure m_procedure;
    TestRig& m_rig;
    EngineOptions m_options;
    std::atomic<EngineState> m_state{EngineState::Idle};
    std::atomic<bool> m_pauseRequested{false}, m_abortRequested{false};
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::function<void(const EngineProgress&)> m_progress;
    RowObserver m_rows;
    EngineObservers m_observers;
};

}  // namespace driftlab::engine
