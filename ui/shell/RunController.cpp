#include "ui/shell/RunController.h"

#include <numeric>

#include "acquisition/modbus/ModbusUrl.h"
#include "ui/models/DeviceHealthModel.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {

engine::RigOptions rigOptionsOf(const RunSetup& setup) {
    engine::RigOptions options;
    options.rig = setup.rig == QLatin1String("sim") ? setup.rig : setup.temperature_url;
    options.seed = setup.seed;
    options.effects = setup.effects;
    options.device_map_path = setup.device_map_path;
    options.controller_url = setup.controller_url;
    options.interferometer_url = setup.interferometer_url;
    options.machine = setup.machine;
    return options;
}

QStringList devicesOf(const RunSetup& setup) {
    if (setup.rig == QLatin1String("sim")) return {QStringLiteral("simulated rig")};
    // Named as DeviceRunSource names them in its events.
    auto endpoint = [](const QString& text) {
        const auto url = modbus::parseModbusUrl(text, nullptr);
        return url ? url->endpoint() : text;
    };
    QStringList devices{
        QStringLiteral("temperature module %1").arg(endpoint(setup.temperature_url))};
    if (!setup.controller_url.isEmpty())
        devices << QStringLiteral("controller %1").arg(endpoint(setup.controller_url));
    if (!setup.interferometer_url.isEmpty()) {
        const auto options = engine::parseInterferometerUrl(setup.interferometer_url, nullptr);
        devices
            << (options
                    ? QStringLiteral("interferometer %1:%2").arg(options->host).arg(options->port)
                    : QStringLiteral("interferometer %1").arg(setup.interferometer_url));
    }
    return devices;
}

RunController::RunController(Session& session, QObject* parent)
    : QObject(parent), m_session(session), m_health(new DeviceHealthModel(this)) {
    qRegisterMetaType<engine::EngineState>();
    qRegisterMetaType<engine::EngineProgress>();
    // 10 Hz is enough for a state and a clock; the dashboard pulls rows itself.
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &RunController::poll);
}

RunController::~RunController() {
    // A window closed during a run: the run is aborted (kept, interrupted),
    // never left running without its logger's owner.
    if (m_engine) m_engine->abort();
    if (m_thread) {
        m_thread->wait();
        delete m_thread;
    }
}

bool RunController::start(QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return false;
    };
    if (m_engine) return fail(tr("a run is in progress"));
    if (m_session.storePath().isEmpty()) return fail(tr("no store is open: open or create one"));
    const RunSetup& setup = m_session.runSetup();
    try {
        m_planned = procedures::planRuns(setup.procedure);
    } catch (const std::exception& e) {
        return fail(tr("procedure %1: %2").arg(setup.procedure.name, QString::fromUtf8(e.what())));
    }
    engine::RigError rigError;
    m_rig = engine::makeRig(rigOptionsOf(setup), setup.procedure, &rigError);
    if (!m_rig) return fail(rigError.toString());

    engine::EngineOptions options;
    options.store_path = m_session.storePath();
    options.speedup = setup.rig == QLatin1String("sim") ? setup.speedup : 0;
    m_engine = std::make_unique<engine::ProcedureEngine>(setup.procedure, *m_rig, options);
    m_engine->setProgressCallback([this](const engine::EngineProgress& p) {
        std::lock_guard lock(m_mutex);
        m_latest = p;
        if (p.run_index >= m_runClock_s.size()) m_runClock_s.resize(p.run_index + 1, 0.0);
        m_runClock_s[p.run_index] = p.time_s;
    });
    m_engine->setRowObserver([this](double t_s, const double* values, std::size_t count) {
        if (m_writeBuffer) m_writeBuffer->append(t_s, {values, count}, nullptr);
    });
    engine::EngineObservers observers;
    observers.run_started = [this](std::size_t, const QString&, const std::vector<QString>& cols) {
        QStringList columns(cols.begin(), cols.end());
        auto buffer = std::make_shared<live::LiveSampleBuffer>(columns);
        auto readings = std::make_shared<live::LiveReadings>();
        m_writeBuffer = buffer.get();
        m_writeReadings = readings.get();
        std::lock_guard lock(m_mutex);
        m_buffer = std::move(buffer);
        m_readings = std::move(readings);
    };
    observers.reading = [this](const PositioningMeasurement& p) {
        if (m_writeReadings) m_writeReadings->append(p);
    };
    observers.device_event = [this](const engine::SourceEvent& e) {
        QMetaObject::invokeMethod(
            this,
            [this, e] {
                m_health->report(e.level, e.source, e.message);
                emit m_session.event(e.level, e.source, e.message);
            },
            Qt::QueuedConnection);
    };
    m_engine->setObservers(std::move(observers));

    {
        std::lock_guard lock(m_mutex);
        m_latest = {};
        m_runClock_s.clear();
        m_buffer.reset();
        m_readings.reset();
        m_campaignId.reset();
        m_error.clear();
    }
    m_health->reset(devicesOf(setup));
    m_temperatureColumns.clear();
    for (const Channel& c : m_rig->campaignHeader(m_planned).channels)
        if (c.quantity == Quantity::Temperature) m_temperatureColumns << c.id;
    m_runShown = -1;
    m_thread = QThread::create([this] {
        QString why;
        const auto id = m_engine->run(&why);
        std::lock_guard lock(m_mutex);
        m_campaignId = id;
        m_error = why;
    });
    m_thread->setObjectName(QStringLiteral("acquisition"));
    connect(m_thread, &QThread::finished, this, &RunController::onThreadEnded,
            Qt::QueuedConnection);
    m_thread->start();
    m_poll.start();
    emit m_session.event(QStringLiteral("info"), QStringLiteral("run"),
                         tr("started '%1' on %2 into %3")
                             .arg(setup.procedure.name, m_rig->describe(), m_session.storePath()));
    poll();
    return true;
}

void RunController::pause() {
    if (m_engine) m_engine->pause();
}
void RunController::resume() {
    if (m_engine) m_engine->resume();
}
void RunController::abort() {
    if (m_engine) m_engine->abort();
}

void RunController::waitForEnd() {
    if (m_thread) m_thread->wait();
    onThreadEnded();
}

double RunController::elapsed_s() const {
    // Not the wall clock: at 600× a 1 h 33 min procedure takes seconds, and
    // the operator compares this with the procedure's planned durations.
    std::lock_guard lock(m_mutex);
    return std::accumulate(m_runClock_s.begin(), m_runClock_s.end(), 0.0);
}

std::shared_ptr<const live::LiveSampleBuffer> RunController::liveBuffer() const {
    std::lock_guard lock(m_mutex);
    return m_buffer;
}

std::shared_ptr<const live::LiveReadings> RunController::liveReadings() const {
    std::lock_guard lock(m_mutex);
    return m_readings;
}

std::optional<double> RunController::nextMeasurement_s() const {
    const std::size_t i = m_progress.run_index;
    if (i >= m_planned.size() || !active()) return std::nullopt;
    for (const rig::MeasurementEvent& m : m_planned[i].programme.measurements)
        if (m.time_s > m_progress.time_s) return m.time_s;
    return std::nullopt;
}

void RunController::poll() {
    if (!m_engine) return;
    engine::EngineProgress latest;
    {
        std::lock_guard lock(m_mutex);
        latest = m_latest;
    }
    latest.state = m_engine->state();
    if (!latest.run.isEmpty() && int(latest.run_index) != m_runShown) {
        m_runShown = int(latest.run_index);
        emit runStarted(m_runShown, latest.run);
    }
    if (latest.store_problem != m_progress.store_problem) {
        // The session's event log is what the operator watches: a store that
        // refuses the rows is theirs to fix (free space) before memory runs out.
        if (!latest.store_problem.isEmpty())
            emit m_session.event(QStringLiteral("error"), QStringLiteral("store"),
                                 tr("%1; the rows from %2 s on are kept in memory and saved once "
                                    "the store takes them again: free space for it now")
                                     .arg(latest.store_problem)
                                     .arg(latest.unsaved_since_s));
        else
            emit m_session.event(QStringLiteral("info"), QStringLiteral("store"),
                                 tr("the store takes the rows again; none is lost"));
    }
    m_progress = latest;
    emit progressChanged(latest);
    if (latest.state != m_state) {
        m_state = latest.state;
        emit stateChanged(m_state);
    }
}

void RunController::onThreadEnded() {
    if (!m_engine) return;  // already handled (waitForEnd, then the queued signal)
    poll();
    m_poll.stop();
    std::optional<qint64> id;
    QString why;
    {
        std::lock_guard lock(m_mutex);
        id = m_campaignId;
        why = m_error;
    }
    const engine::EngineState end = m_engine->state();
    m_thread->deleteLater();
    m_thread = nullptr;
    m_engine.reset();
    m_rig.reset();
    m_state = id ? end : engine::EngineState::Interrupted;
    m_progress.state = m_state;
    emit stateChanged(m_state);
    m_session.notifyStoreChanged();
    if (id) m_session.selectCampaign(id);
    if (!id)
        emit m_session.event(QStringLiteral("error"), QStringLiteral("run"),
                             tr("failed: %1").arg(why));
    else if (end == engine::EngineState::Interrupted)
        emit m_session.event(QStringLiteral("warning"), QStringLiteral("run"),
                             tr("aborted: campaign %1 kept, the run marked interrupted").arg(*id));
    else
        emit m_session.event(QStringLiteral("info"), QStringLiteral("run"),
                             tr("finished: campaign %1").arg(*id));
    emit finished(id.has_value() && end == engine::EngineState::Finished);
}

}  // namespace driftlab::ui
