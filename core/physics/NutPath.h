#pragma once
// The nut's path over a run, cut at the simulation's steps and spread over its
// cells once. An identification simulates the same run for hundreds of
// parameter sets, and where the nut heats which cell depends on the motion
// and the screw's geometry only: the heat coefficients scale it. Spreading
// the strokes over the cells (depositNutHeat) was a quarter of each
// simulation; with the path cut once, each step adds a stored pattern times
// the nut's power.

#include <cstddef>
#include <span>
#include <vector>

#include "core/domain/Run.h"
#include "core/physics/ScrewThermalParameters.h"

namespace driftlab::physics {

/// A stretch of motion at one speed within one step, in screw coordinates.
struct MotionPiece {
    double from_m = 0, to_m = 0;
    double duration_s = 0;
    double omega_rad_s = 0;  ///< screw speed, ≥ 0
};

/// Replaces `pieces` by the parts of `motion` inside [t0, t1) that turn the
/// screw (a standstill heats nothing). `cursor` carries the first segment still
/// to come from one step to the next (segments are in time order). Throws
/// std::invalid_argument where the nut leaves the screw; `pieces` is then
/// unspecified.
void motionPieces(std::span<const MotionSegment> motion, std::size_t& cursor,
                  const ScrewThermalParameters& screw, double t0, double t1,
                  std::vector<MotionPiece>& pieces);

class NutPath {
public:
    struct Piece {
        double omega_rad_s = 0;
        double duration_s = 0;
        std::size_t first_cell = 0, cells = 0;  ///< the cells it heats
        std::size_t offset = 0;                 ///< of its weights in the path
        double total_J_per_W = 0;               ///< Σ of its weights: heat on the screw per watt
    };

    /// Cuts `motion` into `steps` steps of `dt_s` from t = 0 on the grid of
    /// `screw` (its length, lead, fixed end, nut length and cells; the heat
    /// coefficients are not read). Throws std::invalid_argument where the nut
    /// leaves the screw.
    NutPath(const ScrewThermalParameters& screw, std::span<const MotionSegment> motion, double dt_s,
            std::size_t steps);

    /// Whether the path was cut for this screw's geometry and grid, this step,
    /// this many motion segments and this many steps.
    bool fits(const ScrewThermalParameters& screw, double dt_s, std::size_t segments,
              std::size_t steps) const;

    std::size_t steps() const { return m_stepStart.size() - 1; }
    /// The pieces of step k, from k·dt to (k + 1)·dt.
    std::span<const Piece> step(std::size_t k) const {
        return {m_pieces.data() + m_stepStart[k], m_stepStart[k + 1] - m_stepStart[k]};
    }
    /// Joules per watt of nut power for each cell of `piece`, from its first.
    const double* weights(const Piece& piece) const { return m_weights.data() + piece.offset; }

private:
    ScrewThermalParameters m_screw;
    double m_dt_s;
    std::size_t m_segments;
    std::vector<Piece> m_pieces;
    std::vector<std::size_t> m_stepStart;  ///< m_pieces index of each step's first, and the end
    std::vector<double> m_weights;
};

}  // namespace driftlab::physics
