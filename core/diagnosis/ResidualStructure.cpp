#include "core/diagnosis/ResidualStructure.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::diagnosis {
namespace {

double rms(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return v.empty() ? 0.0 : std::sqrt(s / double(v.size()));
}

// The upper middle for an even count, not core/domain/Median.h's mean of the
// two: of two held-out runs' noise the larger, which the thresholds of the
// diagnosis were set with.
double upperMedian(std::vector<double> v) {
    if (v.empty()) return std::nan("");
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// A base residual within the noise level has no positioning structure to
// explain (a sensor's effect): its share would be a ratio of noise.
bool hasPositioningStructure(const ResidualSummary& before, const ResidualSummary& after) {
    return before.error_rms_um > kNoiseLevelTolerance * after.error_noise_um;
}

}  // namespace

double positioningNoise_um(const std::vector<models::RunData>& runs) {
    std::vector<double> differences;
    for (const auto& run : runs) {
        std::map<std::pair<int, double>, double> forward;
        for (const auto& o : run.observations)
            if (o.direction == Direction::Positive) forward[{o.cycle, o.position_mm}] = o.error_um;
        for (const auto& o : run.observations)
            if (o.direction == Direction::Negative)
                if (auto it = forward.find({o.cycle, o.position_mm}); it != forward.end())
                    differences.push_back(o.error_um - it->second);
    }
    if (differences.size() < 5) return std::nan("");
    return rms(differences) / std::sqrt(2.0);
}

double temperatureNoise_K(const std::vector<double>& values) {
    std::vector<double> second;
    for (std::size_t i = 2; i < values.size(); ++i)
        second.push_back(values[i] - 2 * values[i - 1] + values[i - 2]);
    // A robust spread (the nut sensor jumps as the nut moves): 1.4826·MAD ≈ σ.
    std::vector<double> absolute;
    for (double d : second) absolute.push_back(std::abs(d));
    return 1.4826 * upperMedian(absolute) / std::sqrt(6.0);
}

double residualNoise_K(const std::vector<models::ReadingResiduals>& residuals,
                       const QString& channel) {
    std::vector<double> perRun;
    for (const auto& r : residuals)
        for (const auto& sensor : r.sensors)
            if (sensor.channel_id == channel)
                perRun.push_back(temperatureNoise_K(sensor.residual_K));
    return upperMedian(perRun);
}

double soakedStartResidual_K(const std::vector<models::ReadingResiduals>& residuals,
                             const QString& channel) {
    double squares = 0;
    int runs = 0;
    for (const auto& r : residuals)
        for (const auto& sensor : r.sensors) {
            if (sensor.channel_id != channel || sensor.time_s.empty()) continue;
            double sum = 0;
            int n = 0;
            for (std::size_t k = 0; k < sensor.time_s.size(); ++k)
                if (sensor.time_s[k] <= sensor.time_s.front() + 60 &&
                    std::isfinite(sensor.residual_K[k])) {
                    sum += sensor.residual_K[k];
                    ++n;
                }
            if (n == 0) continue;
            squares += std::pow(sum / n, 2);
            ++runs;
        }
    return runs ? std::sqrt(squares / runs) : NAN;
}

QuantityResidual quantityResidual(const std::vector<models::ReadingResiduals>& residuals,
                                  const QString& channel) {
    QuantityResidual q;
    const auto add = [&q](const std::vector<double>& values) {
        for (double v : values) q.sum_squares += v * v;
        q.count += values.size();
    };
    for (const auto& r : residuals) {
        if (channel.isEmpty()) add(r.error_um);
        for (const auto& sensor : r.sensors)
            if (!channel.isEmpty() && sensor.channel_id == channel) add(sensor.residual_K);
    }
    return q;
}

bool ResidualSummary::atNoiseLevel(double tolerance) const {
    const bool positioning = !(error_noise_um > 0) || error_rms_um <= tolerance * error_noise_um;
    const bool temperature =
        worst_channel.isEmpty() || worst_channel_rms_K <= tolerance * worst_channel_noise_K + 0.01;
    return positioning && temperature;
}

double shareAboveNoiseExplained(double before, double after, double noise) {
    return std::clamp((before * before - after * after) / (before * before - noise * noise), 0.0,
                      1.0);
}

double structureExplained(const ResidualSummary& before, const ResidualSummary& after) {
    if (!hasPositioningStructure(before, after)) return 1;
    return shareAboveNoiseExplained(before.error_rms_um, after.error_rms_um, after.error_noise_um);
}

double structureRmsExplained(const ResidualSummary& before, const ResidualSummary& after) {
    if (!hasPositioningStructure(before, after)) return 0;
    return 1 - std::sqrt(1 - structureExplained(before, after));
}

ResidualSummary summarise(const std::vector<models::ReadingResiduals>& residuals,
                          const std::vector<models::RunData>& runs) {
    ResidualSummary s;
    std::vector<double> errors, temperatures;
    std::map<QString, std::vector<double>> perChannel;
    std::map<QString, std::vector<double>> noise;
    for (const auto& r : residuals) {
        errors.insert(errors.end(), r.error_um.begin(), r.error_um.end());
        for (const auto& sensor : r.sensors) {
            temperatures.insert(temperatures.end(), sensor.residual_K.begin(),
                                sensor.residual_K.end());
            auto& c = perChannel[sensor.channel_id];
            c.insert(c.end(), sensor.residual_K.begin(), sensor.residual_K.end());
        }
    }
    for (const auto& run : runs)
        for (const auto& t : run.temperatures)
            if (perChannel.count(t.channel_id))
                noise[t.channel_id].push_back(temperatureNoise_K(t.rise_K.value));
    s.error_rms_um = rms(errors);
    for (double e : errors) s.error_peak_um = std::max(s.error_peak_um, std::abs(e));
    s.temperature_rms_K = rms(temperatures);
    s.error_noise_um = positioningNoise_um(runs);
    for (const auto& [channel, values] : perChannel) {
        const double r = rms(values);
        if (s.worst_channel.isEmpty() || r > s.worst_channel_rms_K) {
            s.worst_channel = channel;
            s.worst_channel_rms_K = r;
            s.worst_channel_noise_K = upperMedian(noise[channel]);
        }
    }
    return s;
}

QString describeStructure(const std::vector<models::ReadingResiduals>& residuals,
                          const std::vector<models::RunData>& runs) {
    // Position thirds × time quarters of the runs.
    double xMin = INFINITY, xMax = -INFINITY, tMax = 0;
    for (const auto& r : residuals)
        for (const auto& p : r.points) {
            xMin = std::min(xMin, p.position_mm);
            xMax = std::max(xMax, p.position_mm);
            tMax = std::max(tMax, p.time_s);
        }
    if (!(xMax > xMin) || !(tMax > 0)) return QStringLiteral("no positioning residual to describe");
    double sum[3][4] = {}, count[3][4] = {};
    for (const auto& r : residuals)
        for (std::size_t j = 0; j < r.points.size(); ++j) {
            const int xb = std::min(2, int(3 * (r.points[j].position_mm - xMin) / (xMax - xMin)));
            const int tb = std::min(3, int(4 * r.points[j].time_s / tMax));
            sum[xb][tb] += r.error_um[j];
            count[xb][tb] += 1;
        }
    int bx = 0, bt = 0;
    double best = 0;
    for (int x = 0; x < 3; ++x)
        for (int t = 0; t < 4; ++t)
            if (count[x][t] > 0 && std::abs(sum[x][t] / count[x][t]) > std::abs(best)) {
                best = sum[x][t] / count[x][t];
                bx = x;
                bt = t;
            }
    QString where = QStringLiteral(
                        "the positioning residual is largest at %1–%2 mm between "
                        "%3 and %4 h (mean %5 µm)")
                        .arg(xMin + (xMax - xMin) * bx / 3, 0, 'f', 0)
                        .arg(xMin + (xMax - xMin) * (bx + 1) / 3, 0, 'f', 0)
                        .arg(tMax * bt / 4 / 3600, 0, 'f', 1)
                        .arg(tMax * (bt + 1) / 4 / 3600, 0, 'f', 1)
                        .arg(best, 0, 'f', 2);

    // What it moves with: correlation with each temperature rise at the readings.
    QString follows;
    double strongest = 0;
    std::map<QString, std::pair<std::vector<double>, std::vector<double>>> pairs;
    for (std::size_t k = 0; k < residuals.size() && k < runs.size(); ++k)
        for (const auto& t : runs[k].temperatures) {
            if (!t.unusable.isEmpty() || t.rise_K.empty()) continue;
            auto& [x, y] = pairs[t.channel_id];
            for (std::size_t j = 0; j < residuals[k].points.size(); ++j) {
                try {
                    x.push_back(
                        models::valueAt(t.rise_K, residuals[k].points[j].time_s, runs[k].run_id));
                    y.push_back(residuals[k].error_um[j]);
                } catch (const models::ModelError&) {
                    // a reading in a gap of this channel: no pair, not an error
                }
            }
        }
    for (const auto& [channel, xy] : pairs) {
        const auto& [x, y] = xy;
        if (x.size() < 5) continue;
        const Eigen::Map<const Eigen::VectorXd> a(x.data(), Eigen::Index(x.size()));
        const Eigen::Map<const Eigen::VectorXd> b(y.data(), Eigen::Index(y.size()));
        const Eigen::VectorXd da = a.array() - a.mean(), db = b.array() - b.mean();
        const double denominator = da.norm() * db.norm();
        const double r = denominator > 0 ? da.dot(db) / denominator : 0;
        if (std::abs(r) > std::abs(strongest)) {
            strongest = r;
            follows = channel;
        }
    }
    if (!follows.isEmpty())
        where += QStringLiteral("; it follows the rise of %1 best (correlation %2)")
                     .arg(follows)
                     .arg(strongest, 0, 'f', 2);
    return where;
}

}  // namespace driftlab::diagnosis
