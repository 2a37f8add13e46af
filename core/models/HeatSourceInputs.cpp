#include "core/models/HeatSourceInputs.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

constexpr double kRpmToRadPerS = 2 * std::numbers::pi / 60;
/// Motion segments may touch within this, s.
constexpr double kTimeTolerance_s = 1e-6;

/// rad/s of screw per mm/min of feed.
double screwRadPerSPerFeed(const RunData& run, const QString& model) {
    if (!run.lead_mm() || !(*run.lead_mm() > 0))
        throw ModelError(QStringLiteral("model '%1' needs the screw lead to turn feed into screw "
                                        "speed; the campaign of run '%2' has no screw lead")
                             .arg(model, run.run_id));
    return kRpmToRadPerS / *run.lead_mm();
}

void requireSignal(const RunData& run, const Signal& signal, const QString& model,
                   const QString& what) {
    if (signal.empty())
        throw ModelError(QStringLiteral("model '%1' needs %2: run '%3' has no samples in %4")
                             .arg(model, what, run.run_id, describeSignal(signal)));
}

PiecewiseInput held(const Signal& signal, double scale) {
    PiecewiseInput input;
    input.time_s = signal.time_s;
    input.value.reserve(signal.value.size());
    for (double v : signal.value) input.value.push_back(std::abs(v) * scale);
    return input;
}

/// Screw speed from the feed_mm_min samples, each held until the next sample.
PiecewiseInput screwSpeedFromFeed(const RunData& run, const QString& model) {
    const double scale = screwRadPerSPerFeed(run, model);
    requireSignal(run, run.feed_mm_min, model, QStringLiteral("the screw speed"));
    requireCoverage(run, run.feed_mm_min);
    return held(run.feed_mm_min, scale);
}

}  // namespace

PiecewiseInput screwSpeed(const RunData& run, const QString& model) {
    if (run.motion.empty()) return screwSpeedFromFeed(run, model);
    const double scale = screwRadPerSPerFeed(run, model);
    std::vector<MotionSegment> segments = run.motion;
    std::stable_sort(
        segments.begin(), segments.end(),
        [](const MotionSegment& a, const MotionSegment& b) { return a.start_s < b.start_s; });
    PiecewiseInput input;
    for (const MotionSegment& s : segments) {
        double start = s.start_s;
        if (!input.time_s.empty()) {
            if (start < input.time_s.back() - kTimeTolerance_s)
                throw ModelError(QStringLiteral("run '%1': motion segments overlap at t = %2 s")
                                     .arg(run.run_id, messageNumber(start)));
            // Logged times carry rounding: a segment may start a hair before the last ended.
            start = std::max(start, input.time_s.back());
        }
        input.time_s.insert(input.time_s.end(), {start, std::max(start, s.end_s)});
        const double speed = s.isDwell() ? 0.0 : std::abs(s.feed_mm_min) * scale;
        input.value.insert(input.value.end(), {speed, 0.0});
    }
    return input;
}

PiecewiseInput spindleSpeed(const RunData& run, const QString& model) {
    if (run.spindle_speed_rpm.name.isEmpty())
        throw ModelError(QStringLiteral("model '%1' needs the spindle speed; this campaign has no "
                                        "speed channel")
                             .arg(model));
    requireSignal(run, run.spindle_speed_rpm, model, QStringLiteral("the spindle speed"));
    requireCoverage(run, run.spindle_speed_rpm);
    return held(run.spindle_speed_rpm, kRpmToRadPerS);
}

}  // namespace driftlab::models
