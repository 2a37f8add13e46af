#pragma once
// One interferometer stream from header to end: parses its lines and turns each
// position reading into a corrected one, with the air of the latest env line
// when the interferometer's own compensation was off. Transport-free, so the
// TCP reader and a file import share it.

#include <optional>
#include <string_view>

#include "core/interferometer/EnvironmentCorrection.h"
#include "core/interferometer/InterferometerLine.h"

namespace driftlab::interferometer {

struct CorrectedReading {
    int line = 0;             ///< line of the stream it came from
    PositionReading reading;  ///< as the interferometer sent it
    double position_mm = 0;   ///< corrected
    double deviation_um = 0;  ///< corrected
    EnvironmentCorrection correction;
};

class InterferometerSession {
public:
    /// An env line older than this (s) before a reading is stale: with
    /// compensation off the reading is refused rather than corrected with old air.
    explicit InterferometerSession(double maxEnvironmentAge_s = 300.0)
        : m_maxEnvironmentAge_s(maxEnvironmentAge_s) {}

    /// A corrected reading for a position line, nothing for the other lines.
    /// Throws InterferometerLineError naming the line (and the field).
    std::optional<CorrectedReading> feed(std::string_view line);

    const InterferometerLineParser& parser() const { return m_parser; }
    const std::optional<EnvironmentReading>& lastEnvironment() const { return m_environment; }
    bool ended() const { return m_parser.ended(); }

private:
    InterferometerLineParser m_parser;
    double m_maxEnvironmentAge_s;
    std::optional<EnvironmentReading> m_environment;
    int m_environmentLine = 0;
    EnvironmentCorrection m_correction;  ///< of m_environment, computed once per env line
};

}  // namespace driftlab::interferometer
