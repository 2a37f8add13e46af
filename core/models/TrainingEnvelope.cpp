#include "core/models/TrainingEnvelope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace driftlab::models {
namespace {

struct Range {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
};

const TemperatureRise* findChannel(const RunData& run, const QString& id) {
    for (const TemperatureRise& t : run.temperatures)
        if (t.channel_id == id && t.unusable.isEmpty() && !t.rise_K.empty()) return &t;
    return nullptr;
}

QString signedKelvin(double value_K) {
    return QStringLiteral("%1%2 K")
        .arg(value_K > -0.005 ? QStringLiteral("+") : QStringLiteral("−"))
        .arg(std::abs(value_K), 0, 'f', 2);
}

}  // namespace

std::vector<RiseBeyondTraining> risesBeyondTraining(const std::vector<RunData>& training,
                                                    const std::vector<RunData>& runs,
                                                    const TrainingEnvelopeOptions& options) {
    // The range of each channel that every training run gives.
    std::map<QString, Range> ranges;
    if (!training.empty())
        for (const TemperatureRise& channel : training.front().temperatures) {
            Range range;
            bool everyRun = true;
            for (const RunData& run : training) {
                const TemperatureRise* t = findChannel(run, channel.channel_id);
                if (!t) {
                    everyRun = false;
                    break;
                }
                const auto [low, high] =
                    std::minmax_element(t->rise_K.value.begin(), t->rise_K.value.end());
                range.low = std::min(range.low, *low);
                range.high = std::max(range.high, *high);
            }
            if (everyRun) ranges[channel.channel_id] = range;
        }

    std::vector<RiseBeyondTraining> beyond;
    for (const RunData& run : runs) {
        std::vector<std::pair<double, RiseBeyondTraining>> ofRun;  // (ranges beyond, finding)
        for (const TemperatureRise& t : run.temperatures) {
            const auto range = ranges.find(t.channel_id);
            if (range == ranges.end() || !t.unusable.isEmpty() || t.rise_K.empty()) continue;
            const Range& r = range->second;
            const double span_K = r.high - r.low;
            const double margin_K =
                std::max(options.min_margin_K, options.margin_of_range * span_K);
            const auto [low, high] =
                std::minmax_element(t.rise_K.value.begin(), t.rise_K.value.end());
            const double below_K = r.low - *low, above_K = *high - r.high;
            if (std::max(below_K, above_K) <= margin_K) continue;
            const double rise_K = below_K > above_K ? *low : *high;
            ofRun.push_back({std::max(below_K, above_K) / std::max(span_K, margin_K),
                             {run.run_id, t.channel_id, t.role, rise_K, r.low, r.high}});
        }
        std::stable_sort(ofRun.begin(), ofRun.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        for (auto& [distance, finding] : ofRun) beyond.push_back(std::move(finding));
    }
    return beyond;
}

QStringList describeRisesBeyondTraining(const std::vector<RiseBeyondTraining>& beyond) {
    QStringList lines;
    QString run;
    QStringList parts;
    auto flush = [&] {
        if (!parts.isEmpty())
            lines << QStringLiteral("%1: %2").arg(run, parts.join(QStringLiteral(", ")));
        parts.clear();
    };
    for (const RiseBeyondTraining& b : beyond) {
        if (b.run != run) {
            flush();
            run = b.run;
        }
        parts << QStringLiteral("%1 (%2) %3 (training runs %4 … %5)")
                     .arg(b.channel, toString(b.role), signedKelvin(b.rise_K),
                          signedKelvin(b.training_low_K), signedKelvin(b.training_high_K));
    }
    flush();
    return lines;
}

std::vector<SpeedBeyondTraining> speedsBeyondTraining(const std::vector<RunData>& training,
                                                      const std::vector<RunData>& runs) {
    constexpr double kMinMargin_rpm = 10, kMarginOfRange = 0.1;
    Range range;
    for (const RunData& run : training) {
        const std::vector<double>& v = run.spindle_speed_rpm.value;
        if (v.empty()) return {};
        const auto [low, high] = std::minmax_element(v.begin(), v.end());
        range.low = std::min(range.low, *low);
        range.high = std::max(range.high, *high);
    }
    if (training.empty()) return {};
    const double margin_rpm = std::max(kMinMargin_rpm, kMarginOfRange * (range.high - range.low));
    std::vector<SpeedBeyondTraining> beyond;
    for (const RunData& run : runs) {
        const std::vector<double>& v = run.spindle_speed_rpm.value;
        if (v.empty()) continue;
        const auto [low, high] = std::minmax_element(v.begin(), v.end());
        const double below = range.low - *low, above = *high - range.high;
        if (std::max(below, above) <= margin_rpm) continue;
        beyond.push_back({run.run_id, run.spindle_speed_rpm.name, below > above ? *low : *high,
                          range.low, range.high});
    }
    return beyond;
}

QStringList describeSpeedsBeyondTraining(const std::vector<SpeedBeyondTraining>& beyond) {
    QStringList lines;
    for (const SpeedBeyondTraining& b : beyond)
        lines << QStringLiteral("%1: %2 (spindle speed) %3 rpm (training runs %4 … %5 rpm)")
                     .arg(b.run, b.channel)
                     .arg(b.speed_rpm, 0, 'f', 0)
                     .arg(b.training_low_rpm, 0, 'f', 0)
                     .arg(b.training_high_rpm, 0, 'f', 0);
    return lines;
}

}  // namespace driftlab::models
