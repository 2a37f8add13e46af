#pragma once
// What a procedure may ask for: what a machine, a thermal channel and the
// store can hold. Beyond these a value is a typo (1e9 for 1e3), and planning
// it would take minutes or all the memory before anything says so; every
// limit is checked, naming its key, before anything is allocated.

namespace driftlab::procedures::limits {

/// A thermal channel needs no faster logging than 1 kHz; one sample an hour is no log.
constexpr double kMinSampleInterval_s = 0.001;
constexpr double kMaxSampleInterval_s = 3600;
/// The longest run a campaign plans: drift tests last hours to days.
constexpr double kMaxRunDuration_s = 30 * 86400.0;
/// Sample rows of one run: about 2 GB in the store at a dozen columns.
constexpr double kMaxRowsPerRun = 2e7;
/// Interferometer readings and motion segments planned in one run (a
/// day's warm-up of 3 s strokes is about 30 000 segments).
constexpr double kMaxMeasurementsPerRun = 1e6;
constexpr double kMaxMotionSegmentsPerRun = 5e6;
/// Positioning targets at a 1 mm pitch; ISO 230-2 asks for at least 5 per metre.
constexpr double kMaxTargetsPerMetre = 1000;
constexpr int kMaxTargets = 10000;
constexpr int kMaxCycles = 1000;
/// The fastest linear axes run at about 2 m/s; slower than 1 mm/min is no test.
constexpr double kMinFeed_mm_min = 1;
constexpr double kMaxFeed_mm_min = 200000;
constexpr double kMaxSpindleSpeed_rpm = 200000;
/// Travel ends within ±100 m of the machine's zero.
constexpr double kMaxTravel_mm = 100000;
/// Dwell at a target, stabilisation threshold.
constexpr double kMaxDwell_s = 3600;
constexpr double kMaxStabilisation_um = 1000;

}  // namespace driftlab::procedures::limits
