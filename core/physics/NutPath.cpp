#include "core/physics/NutPath.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/physics/NutHeatDeposition.h"

namespace driftlab::physics {

void motionPieces(std::span<const MotionSegment> motion, std::size_t& cursor,
                  const ScrewThermalParameters& screw, double t0, double t1,
                  std::vector<MotionPiece>& pieces) {
    pieces.clear();
    // Segments are in time order, so the cursor stays valid while the one
    // before it has ended. (Testing the cursor's own start instead rescanned
    // the whole list on every step of a gap between segments or after the
    // last one: quadratic in the run length.)
    if (cursor > motion.size() || (cursor > 0 && motion[cursor - 1].end_s > t0)) cursor = 0;
    while (cursor < motion.size() && motion[cursor].end_s <= t0) ++cursor;

    const double length = screw.length_m;
    for (std::size_t k = cursor; k < motion.size() && motion[k].start_s < t1; ++k) {
        const MotionSegment& s = motion[k];
        const double a = std::max(s.start_s, t0);
        const double b = std::min(s.end_s, t1);
        if (b <= a) continue;
        const double span = s.end_s - s.start_s;
        auto at = [&](double t) {
            const double axis =
                span > 0 ? s.from_mm + (s.to_mm - s.from_mm) * (t - s.start_s) / span : s.from_mm;
            return (axis - screw.fixed_end_axis_mm) * 1e-3;
        };
        const double from = at(a);
        const double to = at(b);
        if (from < 0 || from > length || to < 0 || to > length)
            throw std::invalid_argument(
                "screw simulation: motion segment at " + std::to_string(s.start_s) + "–" +
                std::to_string(s.end_s) + " s puts the nut at " +
                std::to_string(from < 0 || from > length ? s.from_mm : s.to_mm) +
                " mm, outside the screw");
        const double duration = b - a;
        const double omega = screw.screwSpeed_rad_s((to - from) / duration);
        if (omega != 0) pieces.push_back({from, to, duration, omega});
    }
}

NutPath::NutPath(const ScrewThermalParameters& screw, std::span<const MotionSegment> motion,
                 double dt_s, std::size_t steps)
    : m_screw(screw), m_dt_s(dt_s), m_segments(motion.size()) {
    const auto cells = static_cast<std::size_t>(screw.cells);
    std::vector<double> spread(cells, 0.0);
    std::vector<MotionPiece> inStep;
    std::size_t cursor = 0;
    m_stepStart.reserve(steps + 1);
    // Step times summed as the simulation sums them, so the cut is the same.
    double t0 = 0;
    for (std::size_t k = 0; k < steps; ++k) {
        const double t1 = t0 + dt_s;
        m_stepStart.push_back(m_pieces.size());
        motionPieces(motion, cursor, screw, t0, t1, inStep);
        for (const MotionPiece& m : inStep) {
            Piece piece{m.omega_rad_s, m.duration_s, 0, 0, m_weights.size(), 0};
            piece.total_J_per_W = depositNutHeat(spread, screw.cellWidth_m(), screw.nut_length_m,
                                                 m.from_m, m.to_m, m.duration_s, 1.0);
            const auto heated = [](double w) { return w != 0; };
            const auto first = std::find_if(spread.begin(), spread.end(), heated);
            const auto last = std::find_if(spread.rbegin(), spread.rend(), heated).base();
            if (first < last) {
                piece.first_cell = std::size_t(first - spread.begin());
                piece.cells = std::size_t(last - first);
                m_weights.insert(m_weights.end(), first, last);
                std::fill(first, last, 0.0);
            }
            m_pieces.push_back(piece);
        }
        t0 = t1;
    }
    m_stepStart.push_back(m_pieces.size());
}

bool NutPath::fits(const ScrewThermalParameters& screw, double dt_s, std::size_t segments,
                   std::size_t steps) const {
    return screw.cells == m_screw.cells && screw.length_m == m_screw.length_m &&
           screw.lead_m == m_screw.lead_m && screw.nut_length_m == m_screw.nut_length_m &&
           screw.fixed_end_axis_mm == m_screw.fixed_end_axis_mm && dt_s == m_dt_s &&
           segments == m_segments && steps == this->steps();
}

}  // namespace driftlab::physics
