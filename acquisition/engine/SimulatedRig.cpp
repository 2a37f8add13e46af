#include "acquisition/engine/SimulatedRig.h"

#include <limits>
#include <random>

#include "acquisition/engine/DeviceEvents.h"
#include "core/rig/CampaignSimulator.h"
#include "core/rig/ModuleOutage.h"
#include "core/rig/SpindleTestSimulator.h"

namespace driftlab::engine {
namespace {

class AxisRunSource : public RunSource {
public:
    AxisRunSource(const rig::RigSpec& spec, std::vector<QString> columns, rig::Programme programme,
                  double pitchPhase_rad, unsigned seed)
        : m_run(spec, rig::effectiveScrewParameters(spec), std::move(columns), std::move(programme),
                pitchPhase_rad, seed) {}
    void advanceTo(double until_s, rig::RunOutput& out) override { m_run.advanceTo(until_s, out); }
    double time_s() const override { return m_run.time_s(); }
    bool finished() const override { return m_run.finished(); }
    void replan(const procedures::PlannedRun& run) override {
        m_run.replaceProgramme(run.programme);
    }

private:
    rig::SimulatedAxisRun m_run;
};

/// Spindle and ETVE runs: simulated whole (a lumped model, milliseconds),
/// then given out a sample at a time as if read live.
class PlaybackRunSource : public RunSource {
public:
    PlaybackRunSource(Run run) : m_run(std::move(run)) {}
    void advanceTo(double until_s, rig::RunOutput& out) override {
        const SampleSeries& s = m_run.samples;
        for (; m_next < s.rowCount() && s.time_s[m_next] <= until_s + 1e-9; ++m_next) {
            out.time_s.push_back(s.time_s[m_next]);
            for (const auto& column : s.values) out.rows.push_back(column[m_next]);
        }
        m_t = std::max(m_t, until_s);
    }
    double time_s() const override { return m_t; }
    bool finished() const override { return m_next >= m_run.samples.rowCount(); }
    void replan(const procedures::PlannedRun&) override {}

private:
    Run m_run;
    std::size_t m_next = 0;
    double m_t = 0;
};

/// A run through the temperature module's outages: the rows inside one lose
/// their temperature columns, and the log gets what a device rig writes for a
/// lost module, an error when it stops answering and a gap when it is back.
/// The run always logs on meanwhile, as `on_device_loss: continue`.
class OutageRunSource : public RunSource {
public:
    OutageRunSource(std::unique_ptr<RunSource> run, std::vector<rig::ModuleOutage> outages,
                    std::vector<std::size_t> temperature, std::size_t width)
        : m_run(std::move(run)),
          m_outages(std::move(outages)),
          m_temperature(std::move(temperature)),
          m_width(width) {}
    void advanceTo(double until_s, rig::RunOutput& out) override {
        const std::size_t first = out.time_s.size();
        m_run->advanceTo(until_s, out);
        rig::blankOutages(m_outages, m_temperature, m_width, out, first);
        const QString source = temperatureModuleSource(QStringLiteral("sim"));
        for (const rig::ModuleOutage& o : m_outages) {
            if (m_t < o.from_s && o.from_s <= until_s)
                m_events.push_back(deviceLostEvent(
                    source, QStringLiteral("sim: the module does not answer (simulated outage)")));
            if (m_t < o.to_s && o.to_s <= until_s)
                m_events.push_back(deviceBackEvent(source, QStringLiteral("%1 s").arg(o.from_s),
                                                   QStringLiteral("%1 s").arg(o.to_s),
                                                   o.to_s - o.from_s));
        }
        m_t = until_s;
    }
    double time_s() const override { return m_run->time_s(); }
    bool finished() const override { return m_run->finished(); }
    void replan(const procedures::PlannedRun& run) override { m_run->replan(run); }
    std::vector<SourceEvent> takeEvents() override { return std::exchange(m_events, {}); }

private:
    std::unique_ptr<RunSource> m_run;
    std::vector<rig::ModuleOutage> m_outages;
    std::vector<std::size_t> m_temperature;
    std::size_t m_width;
    double m_t = -std::numeric_limits<double>::infinity();  ///< advanced to
    std::vector<SourceEvent> m_events;
};

}  // namespace

SimulatedRig::SimulatedRig(rig::RigSpec spec) : m_spec(std::move(spec)) {}

QString SimulatedRig::describe() const {
    return QStringLiteral("simulated rig (seed %1)").arg(m_spec.seed);
}

Campaign SimulatedRig::campaignHeader(const std::vector<procedures::PlannedRun>& runs) const {
    bool spindle = false;
    for (const auto& r : runs) spindle = spindle || r.spindle.has_value();
    return rig::rigCampaignHeader(m_spec, spindle);
}

std::unique_ptr<RunSource> SimulatedRig::open(const procedures::PlannedRun& run, std::size_t index,
                                              const std::vector<QString>& columns, QString* error) {
    // The machine's pitch phase first, then one seed per run in procedure order.
    std::mt19937_64 rng(m_spec.seed);
    const double pitchPhase_rad = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    unsigned seed = 0;
    for (std::size_t i = 0; i <= index; ++i) seed = static_cast<unsigned>(rng());
    std::unique_ptr<RunSource> source;
    try {
        if (run.spindle) {
            rig::SpindleTestSpec spec = *run.spindle;
            spec.run_id = run.id;
            spec.seed = seed;
            spec.sample_interval_s = m_spec.sample_interval_s;
            // The room of the rig: a machine at rest drifts with it (ETVE).
            if (run.kind == RunKind::Etve && spec.ambient_swing_K == 0) {
                spec.ambient_swing_K = m_spec.environment.ambient_swing_K;
                spec.ambient_period_s = m_spec.environment.ambient_period_s;
            }
            source = std::make_unique<PlaybackRunSource>(rig::simulateSpindleTest(spec, columns));
        } else {
            source = std::make_unique<AxisRunSource>(m_spec, columns, run.programme, pitchPhase_rad,
                                                     seed);
        }
    } catch (const std::exception& e) {
        if (error)
            *error = QStringLiteral("run %1: %2").arg(run.id, QString::fromStdString(e.what()));
        return nullptr;
    }
    auto outages = rig::outagesOf(m_spec.module_outages, run.id);
    if (outages.empty()) return source;
    auto temperature =
        rig::temperatureColumns(rig::rigCampaignHeader(m_spec, true).channels, columns);
    return std::make_unique<OutageRunSource>(std::move(source), std::move(outages),
                                             std::move(temperature), columns.size());
}

}  // namespace driftlab::engine
