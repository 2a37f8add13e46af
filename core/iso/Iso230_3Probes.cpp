// ISO 230-3 spindle and ETVE drift runs: the displacement probes of a run
// (core/iso/Iso230_3.h). Kept apart from the moving-axis evaluation because
// the data differ: a wide sample series by channel, not readings by target.
#include <algorithm>

#include "core/iso/Iso230_3.h"

namespace driftlab::iso {
namespace {

/// The probe's present samples (missing cells skipped), drift from its first one.
std::optional<ProbeDrift> probeDrift(const Channel& channel, const SampleSeries& samples,
                                     const DriftSettings& settings) {
    const int column = samples.columnIndex(channel.id);
    if (column < 0) return std::nullopt;
    std::vector<std::pair<double, double>> present;  // (time_s, value_um)
    for (std::size_t row = 0; row < samples.rowCount(); ++row)
        if (const double v = samples.values[std::size_t(column)][row]; std::isfinite(v))
            present.emplace_back(samples.time_s[row], v);
    if (present.empty()) return std::nullopt;
    // Times go forward in a valid bundle; sorting keeps a hand-made run honest.
    std::stable_sort(present.begin(), present.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    ProbeDrift p{channel.id, channel.role, present.front().second, {}};
    for (const auto& [time_s, value_um] : present) {
        p.drift.time_s.push_back(time_s);
        p.drift.drift_um.push_back(value_um - p.reference_um);
    }
    summarise(p.drift, settings);
    return p;
}

const ProbeDrift* probeWithRole(const std::vector<ProbeDrift>& probes, ChannelRole role,
                                QString* why) {
    const ProbeDrift* found = nullptr;
    for (const ProbeDrift& p : probes)
        if (p.role == role) {
            if (found) {
                *why = QStringLiteral("two probes with role %1 (%2, %3)")
                           .arg(toString(role), found->channel_id, p.channel_id);
                return nullptr;
            }
            found = &p;
        }
    if (!found) *why = QStringLiteral("no probe with role %1").arg(toString(role));
    return found;
}

/// (drift(to) − drift(from)) at the rows where both probes have a sample.
TiltDrift tilt(const QString& name, const ProbeDrift& from, const ProbeDrift& to,
               const SampleSeries& samples, const DriftSettings& settings) {
    TiltDrift t{name, from.channel_id, to.channel_id, {}, 0, 0};
    const auto& a = samples.values[std::size_t(samples.columnIndex(from.channel_id))];
    const auto& b = samples.values[std::size_t(samples.columnIndex(to.channel_id))];
    std::vector<std::pair<double, double>> rows;
    for (std::size_t row = 0; row < samples.rowCount(); ++row)
        if (std::isfinite(a[row]) && std::isfinite(b[row]))
            rows.emplace_back(samples.time_s[row],
                              (b[row] - to.reference_um) - (a[row] - from.reference_um));
    std::stable_sort(rows.begin(), rows.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    // The reference is the first common sample: a tilt is zero where it starts.
    const double first_um = rows.empty() ? 0 : rows.front().second;
    for (const auto& [time_s, diff_um] : rows) {
        t.drift.time_s.push_back(time_s);
        t.drift.drift_um.push_back(diff_um - first_um);
    }
    summarise(t.drift, settings);
    // µm over mm is mrad; × 1000 gives µrad.
    t.max_tilt_urad = t.drift.max_drift_um / *settings.probe_distance_mm * 1000;
    t.range_urad = t.drift.range_um / *settings.probe_distance_mm * 1000;
    return t;
}

void addTilts(ProbeDriftEvaluation& result, const SampleSeries& samples) {
    const DriftSettings& settings = result.settings;
    if (!settings.probe_distance_mm) {
        result.notes << QStringLiteral(
            "tilts A and B not derived: the distance between the two x (and the two y) "
            "probes along the mandrel is not given (probe_distance_mm; --probe-distance-mm)");
        return;
    }
    const struct {
        const char* name;
        ChannelRole first, second;
    } pairs[] = {{"A", ChannelRole::DriftY, ChannelRole::TiltA},
                 {"B", ChannelRole::DriftX, ChannelRole::TiltB}};
    for (const auto& pair : pairs) {
        QString why;
        const ProbeDrift* from = probeWithRole(result.probes, pair.first, &why);
        const ProbeDrift* to = from ? probeWithRole(result.probes, pair.second, &why) : nullptr;
        if (!to) {
            result.notes
                << QStringLiteral("tilt %1 not derived: %2").arg(QLatin1String(pair.name), why);
            continue;
        }
        TiltDrift t = tilt(QLatin1String(pair.name), *from, *to, samples, settings);
        if (t.drift.time_s.size() < 2)
            result.notes << QStringLiteral(
                                "tilt %1 not derived: %2 and %3 share fewer than "
                                "two sample times")
                                .arg(QLatin1String(pair.name), from->channel_id, to->channel_id);
        else
            result.tilts.push_back(std::move(t));
    }
}

}  // namespace

ProbeDriftEvaluation evaluateProbeDrift(const Campaign& campaign, const Run& run,
                                        const DriftSettings& settings) {
    ProbeDriftEvaluation result;
    result.run_id = run.id;
    result.kind = run.kind;
    result.settings = settings;
    const QString prefix = QStringLiteral("run %1: ").arg(run.id);
    QString why;
    if (!settings.isValid(&why)) {
        result.error = prefix + why;
        return result;
    }
    for (const Channel& channel : campaign.channels) {
        if (channel.quantity != Quantity::Displacement) continue;
        if (auto p = probeDrift(channel, run.samples, settings))
            result.probes.push_back(std::move(*p));
        else
            result.warnings
                << prefix + QStringLiteral("displacement channel %1 has no sample").arg(channel.id);
    }
    if (result.probes.empty()) {
        result.error = prefix + QStringLiteral(
                                    "no displacement channel with samples (a drift "
                                    "probe: role drift_x, drift_y, drift_z, tilt_a, "
                                    "tilt_b or drift)");
        result.warnings.clear();
        return result;
    }
    for (const ProbeDrift& p : result.probes)
        if (p.drift.time_s.size() < 2)
            result.warnings << prefix + QStringLiteral(
                                            "probe %1 has a single sample: its drift "
                                            "is zero by definition")
                                            .arg(p.channel_id);
    if (run.kind == RunKind::Spindle) addTilts(result, run.samples);
    double latest_s = -std::numeric_limits<double>::infinity();
    for (const ProbeDrift& p : result.probes) {
        if (!p.drift.stabilised()) return result;  // stabilised_time_s stays NaN
        latest_s = std::max(latest_s, p.drift.stabilised_time_s);
    }
    result.stabilised_time_s = latest_s;
    return result;
}

}  // namespace driftlab::iso
