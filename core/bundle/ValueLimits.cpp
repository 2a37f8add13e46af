#include "core/bundle/ValueLimits.h"

#include <QRegularExpression>
#include <QStringList>
#include <cmath>

#include "core/domain/MessageText.h"

namespace driftlab::bundle {
namespace {

constexpr double kMinTemperatureC = -60.0;
constexpr double kMaxTemperatureC = 300.0;
constexpr double kKelvinSuspectC = 200.0;
constexpr double kMaxRoomC = 45.0;
constexpr double kMaxDisplacementUm = 10'000.0;
constexpr double kMaxSpeedRpm = 200'000.0;
constexpr double kMaxFeedMmMin = 1'000'000.0;
constexpr double kMaxTorqueNm = 100'000.0;
constexpr double kMaxTimeS = 1e7;

}  // namespace

std::optional<QString> impossibleValue(Quantity quantity, double value, ChannelRole role) {
    switch (quantity) {
        case Quantity::Temperature:
            if (value < kMinTemperatureC || value > kMaxTemperatureC)
                return QStringLiteral(
                           "%1 °C is impossible for a temperature on a machine tool "
                           "(%2…%3 °C)%4")
                    .arg(numberText(value))
                    .arg(numberText(kMinTemperatureC))
                    .arg(numberText(kMaxTemperatureC))
                    .arg(value > 250 && value < 400
                             ? QStringLiteral("; kelvin? DriftLab expects °C")
                             : QString());
            if (value > kKelvinSuspectC)
                return QStringLiteral(
                           "%1 °C looks like kelvin (no part of a feed axis runs that hot); "
                           "DriftLab expects °C")
                    .arg(numberText(value));
            if ((role == ChannelRole::Ambient || role == ChannelRole::Air) && value > kMaxRoomC)
                return QStringLiteral(
                           "%1 °C is no room's or air's temperature in a machine-tool lab "
                           "(at most %2 °C): °F? DriftLab expects °C")
                    .arg(numberText(value))
                    .arg(numberText(kMaxRoomC));
            return std::nullopt;
        case Quantity::Displacement:
            if (std::abs(value) > kMaxDisplacementUm)
                return QStringLiteral(
                           "%1 µm is beyond ±%2 µm for a drift probe (nm instead of µm?)")
                    .arg(numberText(value))
                    .arg(numberText(kMaxDisplacementUm));
            return std::nullopt;
        case Quantity::Speed:
            if (std::abs(value) > kMaxSpeedRpm)
                return QStringLiteral("%1 rpm is beyond ±%2 rpm for a spindle speed")
                    .arg(numberText(value))
                    .arg(numberText(kMaxSpeedRpm));
            return std::nullopt;
    }
    return std::nullopt;
}

std::optional<QString> impossibleAxisValue(const QString& column, double value) {
    if (column == kFeedColumn && std::abs(value) > kMaxFeedMmMin)
        return QStringLiteral("%1 mm/min is beyond ±%2 mm/min for a feed (mm/s or µm/min?)")
            .arg(numberText(value))
            .arg(numberText(kMaxFeedMmMin));
    if (column == kTorqueColumn && std::abs(value) > kMaxTorqueNm)
        return QStringLiteral("%1 N·m is beyond ±%2 N·m for a feed drive's torque")
            .arg(numberText(value))
            .arg(numberText(kMaxTorqueNm));
    return std::nullopt;
}

std::optional<QString> impossibleDeviation(double deviation_um) {
    if (std::abs(deviation_um) > kMaxDisplacementUm)
        return QStringLiteral(
                   "%1 µm is beyond ±%2 µm for a positioning deviation (nm instead "
                   "of µm?)")
            .arg(numberText(deviation_um))
            .arg(numberText(kMaxDisplacementUm));
    return std::nullopt;
}

std::optional<QString> tinyMicrometres(std::size_t count, double largest_um, const QString& what) {
    constexpr double kTinyUm = 0.1;
    if (count < 10 || largest_um >= kTinyUm) return std::nullopt;
    return QStringLiteral(
               "all %1 %2 are within ±%3 µm (largest %4 µm): mm instead of µm? Nothing on a "
               "machine tool is that steady; DriftLab reads them in µm")
        .arg(count)
        .arg(what, numberText(kTinyUm), numberText(largest_um));
}

std::optional<QString> impossibleTime(double time_s) {
    // A logger's clock gives seconds (about 1.8e9 today) or milliseconds
    // (1.8e12) since 1970; a run's own counter in ms stays below either.
    const double t = std::abs(time_s);
    if (t > kMaxTimeS)
        return QStringLiteral("%1 s is beyond %2 s since the run's start (%3)")
            .arg(numberText(time_s))
            .arg(numberText(kMaxTimeS))
            .arg(t >= 1e9 && t < 1e10    ? QStringLiteral("Unix time? time_s counts from the "
                                                             "run's start: subtract its first time")
                 : t >= 1e12 && t < 1e13 ? QStringLiteral("Unix time in ms? time_s counts seconds "
                                                          "from the run's start")
                                         : QStringLiteral("ms instead of s?"));
    return std::nullopt;
}

std::optional<QString> impossibleClockTime(double time_s) {
    return std::abs(time_s) > 1e10 ? impossibleTime(time_s) : std::nullopt;
}

std::optional<HeaderWithUnit> splitHeaderUnit(const QString& header) {
    static const QRegularExpression withUnit(
        QStringLiteral(R"(^\s*([A-Za-z0-9_]+)\s*(?:\[\s*([^\]]+?)\s*\]|\(\s*([^)]+?)\s*\))\s*$)"));
    const QRegularExpressionMatch m = withUnit.match(header);
    if (!m.hasMatch()) return std::nullopt;
    return HeaderWithUnit{m.captured(1), m.hasCaptured(2) ? m.captured(2) : m.captured(3)};
}

}  // namespace driftlab::bundle
