#include "core/interferometer/InterferometerRunBuilder.h"

#include <QSet>
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace driftlab::interferometer {
namespace {

/// Where the machine was sent: the reading less its error. Close to the
/// target whether the export's position column is the measured position or
/// (as some packages write it) the nominal one.
double commanded_mm(const CorrectedReading& r) {
    return r.position_mm - r.deviation_um / 1000.0;
}

QString mm(double value) {
    return QString::number(value, 'g', 10);
}

/// Why the build stops: at the reading's CSV line.
struct Refusal {
    bundle::BundleError error;
};

[[noreturn]] void refuse(const PositioningRunContext& c, int line, const QString& message) {
    throw Refusal{{c.fileName, line, 0, message}};
}

struct Assignment {
    std::size_t target = 0;
    Direction direction = Direction::Positive;
    int cycle = 1;
};

/// Each reading's nearest target; refused when it is further than the tolerance.
std::vector<std::size_t> nearestTargets(const std::vector<CorrectedReading>& readings,
                                        const std::vector<double>& targets,
                                        const PositioningRunContext& c) {
    std::vector<std::size_t> nearest;
    nearest.reserve(readings.size());
    for (const CorrectedReading& r : readings) {
        const double x = commanded_mm(r);
        std::size_t best = 0;
        for (std::size_t t = 1; t < targets.size(); ++t)
            if (std::abs(targets[t] - x) < std::abs(targets[best] - x)) best = t;
        const double off = std::abs(targets[best] - x);
        if (off > c.targetTolerance_mm)
            refuse(c, r.line,
                   QStringLiteral("position %1 mm (deviation %2 µm) is %3 mm from the nearest "
                                  "target %4 mm, more than the tolerance of %5 mm: not a reading "
                                  "at a target")
                       .arg(mm(r.position_mm), mm(r.deviation_um), mm(off), mm(targets[best]),
                            mm(c.targetTolerance_mm)));
        nearest.push_back(best);
    }
    return nearest;
}

/// Directions and cycles from the sequence of targets (the header's rules).
std::vector<Assignment> assign(const std::vector<std::size_t>& targets) {
    std::vector<Assignment> out(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) out[i].target = targets[i];
    // The first reading: the direction towards the next target it differs from.
    for (std::size_t j = 1; j < targets.size(); ++j)
        if (targets[j] != targets[0]) {
            out[0].direction = targets[j] > targets[0] ? Direction::Positive : Direction::Negative;
            break;
        }
    const Direction first = out[0].direction;
    const auto flipped = [](Direction d) {
        return d == Direction::Positive ? Direction::Negative : Direction::Positive;
    };
    for (std::size_t i = 1; i < targets.size(); ++i) {
        Assignment& a = out[i];
        const Assignment& before = out[i - 1];
        a.direction = a.target > before.target   ? Direction::Positive
                      : a.target < before.target ? Direction::Negative
                                                 : flipped(before.direction);
        a.cycle = before.cycle + (a.direction == first && before.direction != first ? 1 : 0);
    }
    return out;
}

struct Cluster {
    double target_mm = 0;
    int readings = 0;
};

std::vector<Cluster> clusters(const std::vector<CorrectedReading>& readings, double tolerance_mm) {
    std::vector<double> x;
    x.reserve(readings.size());
    for (const CorrectedReading& r : readings) x.push_back(commanded_mm(r));
    std::sort(x.begin(), x.end());
    std::vector<Cluster> out;
    std::size_t begin = 0;
    for (std::size_t i = 1; i <= x.size(); ++i) {
        // A cluster spans at most the tolerance from its lowest member, so a
        // dense sweep does not chain into one target.
        if (i < x.size() && x[i] - x[begin] <= tolerance_mm) continue;
        double sum = 0;
        for (std::size_t k = begin; k < i; ++k) sum += x[k];
        // To the µm: targets are round numbers, the mean carries the jitter's rest.
        out.push_back({std::round(sum / double(i - begin) * 1000.0) / 1000.0, int(i - begin)});
        begin = i;
    }
    return out;
}

/// The cycles most targets show: half the most common number of readings at
/// a target (one per direction and cycle), rounded up.
int typicalCycles(const std::vector<Cluster>& found) {
    std::map<int, int> sizes;
    for (const Cluster& c : found) ++sizes[c.readings];
    int mode = 0, seen = 0;
    for (const auto& [size, count] : sizes)
        if (count >= seen) std::tie(mode, seen) = std::pair{size, count};
    return (mode + 1) / 2;
}

QString directionText(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-");
}

}  // namespace

std::vector<double> clusterTargets(const std::vector<CorrectedReading>& readings,
                                   double tolerance_mm) {
    std::vector<double> targets;
    for (const Cluster& c : clusters(readings, tolerance_mm)) targets.push_back(c.target_mm);
    return targets;
}

PositioningRunBuild buildPositioningCampaign(const std::vector<CorrectedReading>& readings,
                                             const PositioningRunContext& c) {
    PositioningRunBuild build;
    try {
        if (readings.empty()) refuse(c, 0, QStringLiteral("no readings to build a run from"));
        std::vector<double> targets = c.targets_mm;
        const bool inferred = targets.empty();
        if (inferred) {
            // A cluster with fewer readings than the cycles most targets show
            // is no target (a park position, a stray stop): refused before
            // it could break the sequence of directions.
            const std::vector<Cluster> found = clusters(readings, c.targetTolerance_mm);
            const int cycles = typicalCycles(found);
            for (const Cluster& cluster : found)
                if (cluster.readings >= cycles) targets.push_back(cluster.target_mm);
            for (const CorrectedReading& r : readings) {
                const double x = commanded_mm(r);
                for (const Cluster& cluster : found)
                    if (cluster.readings < cycles &&
                        std::abs(cluster.target_mm - x) <= c.targetTolerance_mm)
                        refuse(c, r.line,
                               QStringLiteral("position %1 mm is at no target: %2 reading(s) "
                                              "near %3 mm, where a target of this run has "
                                              "one in each of its %4 cycles")
                                   .arg(mm(r.position_mm))
                                   .arg(cluster.readings)
                                   .arg(mm(cluster.target_mm))
                                   .arg(cycles));
            }
        }
        std::sort(targets.begin(), targets.end());
        targets.erase(std::unique(targets.begin(), targets.end()), targets.end());

        if (targets.size() < 2)
            refuse(c, readings.front().line,
                   QStringLiteral("the readings are at %1 target(s) (%2 mm): an ISO 230-2 run "
                                  "needs at least 2")
                       .arg(targets.size())
                       .arg(targets.empty() ? QString() : mm(targets.front())));

        std::vector<Assignment> assigned = assign(nearestTargets(readings, targets, c));
        if (inferred) {
            // A cluster missing from a cycle is no target either (the readings
            // of an aborted last cycle): refused, as the cycles would not pair.
            const int cycles = assigned.back().cycle;
            std::vector<QSet<int>> cyclesOf(targets.size());
            for (const Assignment& a : assigned) cyclesOf[a.target].insert(a.cycle);
            for (std::size_t i = 0; i < readings.size(); ++i)
                if (cyclesOf[assigned[i].target].size() != cycles)
                    refuse(c, readings[i].line,
                           QStringLiteral("position %1 mm: the readings at target %2 mm are "
                                          "in %3 of the run's %4 cycles, a target has them in "
                                          "every cycle (a cycle cut short?)")
                               .arg(mm(readings[i].position_mm), mm(targets[assigned[i].target]))
                               .arg(cyclesOf[assigned[i].target].size())
                               .arg(cycles));
        }
        Run run;
        run.id = c.runId;
        run.kind = RunKind::Positioning;
        run.range_mm = RangeMm{targets.front(), targets.back()};
        std::map<std::tuple<int, std::size_t, Direction>, int> lineOf;
        const double t0 = readings.front().reading.time_s;
        for (std::size_t i = 0; i < readings.size(); ++i) {
            const Assignment& a = assigned[i];
            const auto [it, fresh] =
                lineOf.emplace(std::tuple{a.cycle, a.target, a.direction}, readings[i].line);
            if (!fresh)
                refuse(c, readings[i].line,
                       QStringLiteral("a second reading at target %1 mm, direction %2, in "
                                      "cycle %3 (the first is line %4): the sequence is not "
                                      "a linear ISO 230-2 cycle")
                           .arg(mm(targets[a.target]), directionText(a.direction))
                           .arg(a.cycle)
                           .arg(it->second));
            PositioningMeasurement m;
            m.time_s = readings[i].reading.time_s - t0;  // a run's times count from its start
            m.cycle = a.cycle;
            m.target_mm = targets[a.target];
            m.direction = a.direction;
            m.deviation_um = readings[i].deviation_um;
            run.positioning.push_back(m);
        }
        run.description =
            QStringLiteral(
                "ISO 230-2 positioning run imported from %1: %2 readings, %3 targets, "
                "%4 cycles")
                .arg(c.fileName)
                .arg(readings.size())
                .arg(targets.size())
                .arg(assigned.back().cycle);

        Campaign campaign;
        campaign.name = c.campaignName;
        campaign.machine.name = c.machine;
        campaign.machine.axis = c.axis;
        campaign.screw = c.screw;
        campaign.nut_length_mm = c.nut_length_mm;
        campaign.interferometer = Interferometer{0, c.environmentCompensation, {}};
        campaign.runs.push_back(std::move(run));
        build.campaign = std::move(campaign);
    } catch (const Refusal& r) {
        build.error = r.error;
    }
    return build;
}

}  // namespace driftlab::interferometer
