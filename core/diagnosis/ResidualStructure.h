#pragma once
// Is what the model leaves noise or structure? The noise of each kind of
// reading is estimated from the data itself (never from the model), and
// structure is described where a test engineer would look: where in position
// and time the positioning residual sits and what it moves with.

#include <QString>
#include <cmath>
#include <vector>

#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

/// Noise of one thermal-error observation, µm: the forward and backward
/// readings of one target in one pass are seconds apart, so their difference
/// is noise (√2·σ) and nothing thermal. NaN without such pairs.
double positioningNoise_um(const std::vector<models::RunData>& runs);

/// Noise of a temperature channel, K: white noise gives second differences of
/// variance 6σ², a smooth temperature none.
double temperatureNoise_K(const std::vector<double>& values);

/// Noise of a sensor's residual, K: temperatureNoise_K of the residual, median
/// over the runs; NaN when no run has the sensor. From the residual, not the
/// reading: the nut sensor's reading jumps as the nut moves, which the model
/// follows.
double residualNoise_K(const std::vector<models::ReadingResiduals>& residuals,
                       const QString& channel);

/// A residual within this many times its noise estimate is at noise level.
constexpr double kNoiseLevelTolerance = 1.5;

struct ResidualSummary {
    double error_rms_um = 0, error_peak_um = 0;
    double temperature_rms_K = 0;  ///< over all screw sensors
    QString worst_channel;         ///< the sensor with the largest residual RMS
    double worst_channel_rms_K = 0;
    double worst_channel_noise_K = 0;
    double error_noise_um = 0;
    /// Residual at noise level (within `tolerance` × the noise estimates).
    bool atNoiseLevel(double tolerance = kNoiseLevelTolerance) const;
};

/// The share of a residual's mean square above its noise that a model
/// removes: (before² − after²) / (before² − noise²), clamped to [0, 1]; the
/// caller makes sure `before` stands above the noise.
double shareAboveNoiseExplained(double before, double after, double noise);

/// The share of the positioning structure, the mean square above the reading
/// noise, that a model explains: (before² − after²) / (before² − noise²) in
/// [0, 1]; 1 when it leaves no more than the noise, or when `before` is at
/// noise level in positioning (kNoiseLevelTolerance: a sensor's effect).
double structureExplained(const ResidualSummary& before, const ResidualSummary& after);

/// How much of the positioning structure's RMS a model removes, the reading
/// noise taken out of before and after: 1 − √((after² − noise²) / (before² −
/// noise²)), read on the same scale as 1 − after/before, which near the noise
/// understates it (the noise stays in both). 0 when `before` is at noise level
/// in positioning: there is no positioning structure (a sensor's effect).
double structureRmsExplained(const ResidualSummary& before, const ResidualSummary& after);

ResidualSummary summarise(const std::vector<models::ReadingResiduals>& residuals,
                          const std::vector<models::RunData>& runs);

/// What a model leaves of one quantity: the positioning error (`channel`
/// empty, µm) or one temperature sensor's reading (K).
struct QuantityResidual {
    double sum_squares = 0;
    std::size_t count = 0;
    double rms() const { return count ? std::sqrt(sum_squares / double(count)) : 0.0; }
};

QuantityResidual quantityResidual(const std::vector<models::ReadingResiduals>& residuals,
                                  const QString& channel);

/// A sensor's residual at the soaked start, K: its mean over the first minute
/// of each run, where no heat has acted yet and the screw has the room
/// temperature it soaked in; the RMS of those means over the runs. NaN when no
/// run has the sensor.
double soakedStartResidual_K(const std::vector<models::ReadingResiduals>& residuals,
                             const QString& channel);

/// Where the positioning residual sits (position band × time band with the
/// largest mean) and which temperature rise it follows best, in words.
QString describeStructure(const std::vector<models::ReadingResiduals>& residuals,
                          const std::vector<models::RunData>& runs);

}  // namespace driftlab::diagnosis
