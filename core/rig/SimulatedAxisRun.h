#pragma once
// One feed-axis run on the simulated rig, stepped in time: the screw
// simulation driven by a programme's motion, the room, the air and the
// structure around it, the sensors, the drive and the interferometer as a
// real rig logs them. simulateCampaign() runs it to the end in one go; the
// acquisition engine advances it a sample at a time, at any speed-up, and a
// resumed run replays it silently to where the log stopped (it is
// deterministic for a seed, so the replay is the same run).

#include <QString>
#include <functional>
#include <memory>
#include <vector>

#include "core/domain/Run.h"
#include "core/physics/ScrewThermalModel.h"
#include "core/rig/MovingStateProgramme.h"
#include "core/rig/RigSpec.h"

namespace driftlab::rig {

/// What a run produced while it was advanced: sample rows (row-major, one
/// value per sample column, NaN = not logged) and interferometer readings.
struct RunOutput {
    std::vector<double> time_s;
    std::vector<double> rows;  ///< time_s.size() × column count
    std::vector<PositioningMeasurement> readings;
    void clear() {
        time_s.clear();
        rows.clear();
        readings.clear();
    }
};

/// The rows of `out` as a column-major series.
SampleSeries toSampleSeries(const RunOutput& out, const std::vector<QString>& columns);

/// Bearing-seat sensors sit 2.5 mm inside the screw ends, mm on the axis.
double bearingSeat_mm(const physics::ScrewThermalParameters& screw, bool fixedEnd);

class SimulatedAxisRun {
public:
    /// `screw` is the rig's effective screw (effectiveScrewParameters), `columns`
    /// the campaign's sample columns, `pitchPhase_rad` the machine's (one per
    /// campaign), `seed` the run's.
    SimulatedAxisRun(const RigSpec& spec, const physics::ScrewThermalParameters& screw,
                     std::vector<QString> columns, Programme programme, double pitchPhase_rad,
                     unsigned seed);
    ~SimulatedAxisRun();
    SimulatedAxisRun(const SimulatedAxisRun&) = delete;
    SimulatedAxisRun& operator=(const SimulatedAxisRun&) = delete;

    /// Steps whole physics steps until the run time reaches `until_s` (or the
    /// programme ends), appending the samples and readings that fall due. The
    /// first call also logs the sample at time 0.
    void advanceTo(double until_s, RunOutput& out);
    double time_s() const;
    double duration_s() const;
    bool finished() const;
    const Programme& programme() const;
    /// A programme identical to the current one up to time_s() and different
    /// after it (ISO 230-3: the warm-up ended early at stabilisation).
    void replaceProgramme(Programme programme);
    /// Called at every logged sample with the true screw state.
    void setSampleObserver(std::function<void(const physics::ScrewThermalModel&)> observer);

private:
    struct State;
    std::unique_ptr<State> m;
};

}  // namespace driftlab::rig
