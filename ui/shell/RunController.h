#pragma once
// The GUI thread's facade of the procedure engine: runs Session::runSetup()
// into the session's store on an acquisition thread of its own, never the
// GUI thread. Pause, resume and abort go straight to the engine (thread-safe);
// state and progress come back through a GUI timer reading what the engine
// thread last stored (the engine reports every sample: a queued signal per
// sample would flood the GUI at full rate). Each run gets its own live
// buffer of rows and list of interferometer readings for the dashboard;
// device events go to Session::event once per incident and to the health model.

#include <QObject>
#include <QThread>
#include <QTimer>
#include <memory>
#include <mutex>

#include "acquisition/engine/ProcedureEngine.h"
#include "acquisition/engine/RigFactory.h"
#include "acquisition/live/LiveReadings.h"
#include "acquisition/live/LiveSampleBuffer.h"

namespace driftlab::ui {

class Session;
struct RunSetup;
class DeviceHealthModel;

/// The rig options of a run set-up (RunSetup holds the GUI's fields).
engine::RigOptions rigOptionsOf(const RunSetup& setup);
/// The devices of a set-up as their events name them.
QStringList devicesOf(const RunSetup& setup);

class RunController : public QObject {
    Q_OBJECT
public:
    explicit RunController(Session& session, QObject* parent = nullptr);
    ~RunController() override;

    /// Starts the session's run set-up; false with `error` (nothing started).
    bool start(QString* error);
    void pause();
    void resume();
    void abort();
    /// Blocks until the acquisition thread has ended (tests, shutdown).
    void waitForEnd();

    bool active() const { return m_engine != nullptr; }
    engine::EngineState state() const { return m_state; }
    engine::EngineProgress progress() const { return m_progress; }
    /// Run time of the next planned measurement of the current run, if any.
    std::optional<double> nextMeasurement_s() const;
    /// The current run's live rows and readings (null before its first row).
    std::shared_ptr<const live::LiveSampleBuffer> liveBuffer() const;
    std::shared_ptr<const live::LiveReadings> liveReadings() const;
    DeviceHealthModel* health() const { return m_health; }
    /// The temperature channels of the campaign being run (plotted together).
    QStringList temperatureColumns() const { return m_temperatureColumns; }
    /// The procedure's own clock, s: the run time reached in each of its
    /// runs, summed. Simulated time on a sped-up simulated rig, pauses not
    /// counted, and kept once the procedure has ended (what the status bar
    /// shows after the run).
    double elapsed_s() const;

signals:
    void stateChanged(driftlab::engine::EngineState state);
    void progressChanged(const driftlab::engine::EngineProgress& progress);
    /// A run of the procedure began: its live buffer is new (times restart at 0).
    void runStarted(int index, const QString& run);
    void finished(bool ok);

private:
    void poll();
    void onThreadEnded();

    Session& m_session;
    DeviceHealthModel* m_health;
    QTimer m_poll;
    std::unique_ptr<engine::TestRig> m_rig;
    std::unique_ptr<engine::ProcedureEngine> m_engine;
    QThread* m_thread = nullptr;
    std::vector<procedures::PlannedRun> m_planned;
    engine::EngineState m_state = engine::EngineState::Idle;
    engine::EngineProgress m_progress;
    int m_runShown = -1;
    QStringList m_temperatureColumns;

    // Shared with the engine thread.
    mutable std::mutex m_mutex;
    engine::EngineProgress m_latest;                   // guarded
    std::vector<double> m_runClock_s;                  // guarded, run time per run
    std::shared_ptr<live::LiveSampleBuffer> m_buffer;  // guarded
    std::shared_ptr<live::LiveReadings> m_readings;    // guarded
    std::optional<qint64> m_campaignId;                // guarded, set at the end
    QString m_error;                                   // guarded, set at the end
    live::LiveSampleBuffer* m_writeBuffer = nullptr;   // engine thread only
    live::LiveReadings* m_writeReadings = nullptr;     // engine thread only
};

}  // namespace driftlab::ui
