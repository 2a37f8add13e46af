#pragma once
// An interferometer software's CSV export as vendor packages write it: their
// own column names ("Target [mm]", "Position (mm)", "Error [µm]", "Time [s]"),
// ';'-separated with decimal commas, and no cycle or direction column. Linear
// ISO 230-2 cycles: up over the targets, the last one approached again from
// above after the overrun, down, the first one again from below. Each stop
// overruns its approach by a jitter within ±0.05 mm; the position is where the
// axis stopped and the error what the interferometer measured there.
#include <QByteArray>
#include <QString>
#include <cmath>
#include <vector>

namespace driftlab::test {

struct VendorReading {
    double time_s = 0;
    double target_mm = 0;
    bool positive = true;
    int cycle = 1;
    double position_mm = 0;
    double error_um = 0;
};

/// `cycles` bidirectional cycles over `targets`, seeded (the same each time).
inline std::vector<VendorReading> vendorReadings(const std::vector<double>& targets, int cycles) {
    std::vector<VendorReading> out;
    int k = 0;
    const auto stop = [&](int cycle, double target, bool positive) {
        VendorReading r;
        r.time_s = 12.5 * k;
        r.target_mm = target;
        r.positive = positive;
        r.cycle = cycle;
        // A deterministic jitter in ±50 µm (the overrun), a slope of 8 µm/m
        // and 3 µm of reversal error: rounded as the export writes them.
        const double jitter_um = 50.0 * std::sin(1.7 * k + 0.3);
        r.error_um = std::round((0.008 * target + (positive ? 0 : -3.0) + jitter_um) * 100) / 100;
        r.position_mm = target + r.error_um / 1000.0;
        out.push_back(r);
        ++k;
    };
    for (int c = 1; c <= cycles; ++c) {
        for (double t : targets) stop(c, t, true);
        for (auto it = targets.rbegin(); it != targets.rend(); ++it) stop(c, *it, false);
    }
    return out;
}

/// One line of the export, with decimal commas.
inline QByteArray vendorLine(const VendorReading& r) {
    return QString::asprintf("%.3f;%.5f;%.2f;%.1f\n", r.target_mm, r.position_mm, r.error_um,
                             r.time_s)
        .replace(QLatin1Char('.'), QLatin1Char(','))
        .toUtf8();
}

inline QByteArray vendorHeader() {
    return QByteArray("Target [mm];Position (mm);Error [µm];Time [s]\n");
}

inline QByteArray vendorCsv(const std::vector<VendorReading>& readings) {
    QByteArray text = vendorHeader();
    for (const VendorReading& r : readings) text += vendorLine(r);
    return text;
}

}  // namespace driftlab::test
