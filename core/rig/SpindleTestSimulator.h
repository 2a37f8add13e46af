#pragma once
// ISO 230-3 spindle test on the simulated rig: a speed programme (blocks with
// stops) heats the spindle head and, more slowly, the column
// (SpindleThermalNetwork); five temperature sensors sit on the head and the
// column, five non-contact probes see the tool-side drift (x, y, z) and two
// tilts. The probes see mostly nodes no sensor is on (the shaft, the column
// core), so the drift lags every sensor, as on a real machine.

#include <QString>
#include <vector>

#include "core/domain/Campaign.h"

namespace driftlab::rig {

struct SpeedBlock {
    double duration_s = 0;
    double speed_rpm = 0;  ///< 0 = stop
};

struct SpindleTestSpec {
    QString run_id = QStringLiteral("SP1");
    std::vector<SpeedBlock> blocks{{1800, 3000}, {1800, 6000}, {900, 0}, {1800, 9000}, {3600, 0}};
    double sample_interval_s = 5;
    double ambient_C = 20;
    /// The room's slow swing: ambient_C + swing·sin(2πt/period). Housing and
    /// column follow it with their time constants, so a machine at rest still
    /// drifts (an ETVE run). 0 leaves the room constant.
    double ambient_swing_K = 0;
    double ambient_period_s = 12 * 3600;
    /// Spindle for a speed programme, Etve for a machine at rest in a varying room.
    RunKind kind = RunKind::Spindle;
    /// Each probe reading's noise (1 σ). 0 gives the drift itself, with the
    /// same thermometer readings: what a perfect model would predict.
    double probe_noise_um = 0.1;
    unsigned seed = 1;
};

/// The channels a spindle run logs (added to a campaign that lacks them).
std::vector<Channel> spindleTestChannels();

/// Speed programme `index` (1, 2, …) as run SP<index>: SP1 is the default
/// programme; the others step down, cycle, ramp, and (6 and beyond) draw
/// random blocks, so that held-out runs test motion the training did not.
SpindleTestSpec spindleTestProgramme(int index);

/// Simulates the run; the campaign must already hold the spindleTestChannels().
Run simulateSpindleTest(const SpindleTestSpec& spec, const std::vector<QString>& sampleColumns);

}  // namespace driftlab::rig
