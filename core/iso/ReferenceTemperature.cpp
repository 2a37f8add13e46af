#include "core/iso/ReferenceTemperature.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/domain/MessageText.h"

namespace driftlab::iso {

namespace {

/// The mean over `columns` at each sample time that has at least one of them.
struct MeanSeries {
    std::vector<double> time_s;
    std::vector<double> value;
};

MeanSeries meanOf(const Run& run, const QStringList& channels) {
    std::vector<int> columns;
    for (const QString& id : channels)
        if (const int c = run.samples.columnIndex(id); c >= 0) columns.push_back(c);
    MeanSeries series;
    for (std::size_t row = 0; row < run.samples.rowCount(); ++row) {
        double sum = 0;
        int count = 0;
        for (int c : columns)
            if (const double v = run.samples.values[c][row]; std::isfinite(v)) sum += v, ++count;
        if (count == 0) continue;
        series.time_s.push_back(run.samples.time_s[row]);
        series.value.push_back(sum / count);
    }
    return series;
}

/// Linear interpolation, held constant beyond the ends.
double valueAt(const MeanSeries& series, double t_s) {
    const auto& t = series.time_s;
    if (t_s <= t.front()) return series.value.front();
    if (t_s >= t.back()) return series.value.back();
    const auto upper = std::size_t(std::upper_bound(t.begin(), t.end(), t_s) - t.begin());
    const double w = (t_s - t[upper - 1]) / (t[upper] - t[upper - 1]);
    return series.value[upper - 1] * (1 - w) + series.value[upper] * w;
}

std::optional<TemperatureSummary> summarise(const Run& run, const QStringList& channels,
                                            double start_s, double end_s) {
    const MeanSeries series = meanOf(run, channels);
    if (series.time_s.empty()) return std::nullopt;
    TemperatureSummary s;
    s.channels = channels;
    s.min_C = std::numeric_limits<double>::infinity();
    s.max_C = -s.min_C;
    double sum = 0;
    for (std::size_t i = 0; i < series.time_s.size(); ++i) {
        if (series.time_s[i] < start_s || series.time_s[i] > end_s) continue;
        s.min_C = std::min(s.min_C, series.value[i]);
        s.max_C = std::max(s.max_C, series.value[i]);
        sum += series.value[i];
        ++s.samples;
    }
    // Start and end at the first and last reading, also when no sample falls
    // between them (a short test logged every minute).
    s.start_C = valueAt(series, start_s);
    s.end_C = valueAt(series, end_s);
    if (s.samples == 0) {
        s.min_C = std::min(s.start_C, s.end_C);
        s.max_C = std::max(s.start_C, s.end_C);
        s.mean_C = (s.start_C + s.end_C) / 2;
    } else {
        s.min_C = std::min({s.min_C, s.start_C, s.end_C});
        s.max_C = std::max({s.max_C, s.start_C, s.end_C});
        s.mean_C = sum / s.samples;
    }
    return s;
}

QStringList channelsOfRole(const Campaign& campaign, ChannelRole role, int most) {
    QStringList ids;
    for (const Channel& c : campaign.channels)
        if (c.quantity == Quantity::Temperature && c.role == role && ids.size() < most) ids << c.id;
    return ids;
}

}  // namespace

QStringList materialChannels(const Campaign& campaign, const TemperatureSetting& setting,
                             QString* error) {
    if (setting.material_channels.isEmpty())
        return channelsOfRole(campaign, ChannelRole::Structure, 3);
    for (const QString& id : setting.material_channels) {
        const Channel* channel = campaign.findChannel(id);
        if (!channel || channel->quantity != Quantity::Temperature) {
            if (error)
                *error = QStringLiteral(
                             "material thermometer %1: not a temperature channel of "
                             "campaign %2")
                             .arg(quotedText(id), quotedText(campaign.name));
            return {};
        }
    }
    return setting.material_channels;
}

TestEnvironment testEnvironment(const Campaign& campaign, const Run& run,
                                const QStringList& materials) {
    TestEnvironment env;
    if (!run.positioning.empty()) {
        const auto [low, high] =
            std::minmax_element(run.positioning.begin(), run.positioning.end(),
                                [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
        env.start_s = low->time_s;
        env.end_s = high->time_s;
    }
    QStringList air = channelsOfRole(campaign, ChannelRole::Air, 3);
    if (air.isEmpty()) {
        air = channelsOfRole(campaign, ChannelRole::Ambient, 3);
        if (!air.isEmpty())
            env.notes << QStringLiteral(
                "no channel of role air: the ambient thermometer stands "
                "for the air temperature");
    }
    env.air = summarise(run, air, env.start_s, env.end_s);
    if (!env.air) env.notes << QStringLiteral("no air temperature logged during the test");
    if (!materials.isEmpty()) env.material = summarise(run, materials, env.start_s, env.end_s);
    if (!env.material)
        env.notes << QStringLiteral("no material temperature logged during the test");
    return env;
}

std::optional<std::vector<Reading>> readingsAt20C(const Campaign& campaign, const Run& run,
                                                  const TemperatureSetting& setting,
                                                  const QStringList& materials,
                                                  Normalisation* normalisation, QString* error) {
    Normalisation n;
    std::vector<Reading> readings = readingsOf(run);
    if (setting.machine_compensates) {
        n.mode = Normalisation::Mode::MachineCompensates;
        n.description = QStringLiteral(
            "not normalised by DriftLab: the machine's own temperature compensation refers its "
            "positions to 20 °C");
    } else if (!setting.normalise) {
        n.mode = Normalisation::Mode::NotNormalised;
        n.description = QStringLiteral(
            "not normalised to 20 °C: the deviations include the expansion of the machine at "
            "its test temperature");
    } else {
        n.mode = Normalisation::Mode::Normalised;
        const std::optional<double> alpha = setting.expansion_per_K ? setting.expansion_per_K
                                            : campaign.screw
                                                ? std::optional<double>(campaign.screw->alpha_per_K)
                                                : std::nullopt;
        if (!alpha) {
            if (error)
                *error = QStringLiteral(
                    "normalising to 20 °C needs an expansion coefficient: "
                    "give temperature.expansion_per_K or the campaign's screw");
            return std::nullopt;
        }
        n.expansion_per_K = *alpha;
        const MeanSeries series = meanOf(run, materials);
        if (series.time_s.empty() && !setting.material_temperature_C) {
            if (error)
                *error = QStringLiteral(
                             "normalising run %1 to 20 °C needs a material temperature: no "
                             "material thermometer (%2) has a sample; give "
                             "temperature.material_temperature_C or material_channels, or say "
                             "temperature.machine_compensates or normalise false")
                             .arg(quotedText(run.id), materials.isEmpty()
                                                          ? QStringLiteral("none of role structure")
                                                          : quotedList(materials));
            return std::nullopt;
        }
        double sum = 0;
        for (Reading& r : readings) {
            const std::size_t i = std::size_t(&r - readings.data());
            const double theta_C = series.time_s.empty()
                                       ? *setting.material_temperature_C
                                       : valueAt(series, run.positioning[i].time_s);
            const double correction_um = *alpha * (theta_C - 20) * r.target_mm * 1000;
            r.deviation_um -= correction_um;
            n.largest_correction_um = std::max(n.largest_correction_um, std::abs(correction_um));
            sum += theta_C;
        }
        n.mean_material_C = readings.empty() ? 20 : sum / double(readings.size());
        n.description =
            QStringLiteral(
                "normalised to 20 °C: x − α·(θ − 20 °C)·P with α = %1/K, θ %2 "
                "(mean %3 °C); largest correction %4 µm")
                .arg(numberText(*alpha),
                     series.time_s.empty() ? QStringLiteral("declared %1 °C")
                                                 .arg(numberText(*setting.material_temperature_C))
                                           : QStringLiteral("the mean of %1 at each reading")
                                                 .arg(quotedList(materials)),
                     QString::number(n.mean_material_C, 'f', 2),
                     QString::number(n.largest_correction_um, 'f', 3));
    }
    if (normalisation) *normalisation = n;
    return readings;
}

}  // namespace driftlab::iso
