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

}  // namespace driftlab::models
