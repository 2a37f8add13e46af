#pragma once
// The interferometer line protocol (docs/interferometer.md): one record per
// line, comma-separated, '.' decimals, units fixed by the field names.
//
//   # a comment                          (and blank lines: ignored)
//   header,compensation=off[,reference=vacuum|standard-air|<n0>][,wavelength_nm=632.991]
//   env,time_s,air_C,pressure_Pa,humidity_pct[,material_C]
//   time_s,position_mm,deviation_um
//   end
//
// The header comes first and once; `end` closes the stream (a peer that closes
// without it broke off). Parsing is strict: every error names the line number,
// the field and, where it looks like one, the unit mix-up.

#include <QString>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "core/interferometer/AirRefractiveIndex.h"

namespace driftlab::interferometer {

struct InterferometerHeader {
    bool compensationOn = true;
    /// n0 the interferometer converted fringes with when compensation is off.
    double assumedIndex = 1.0;
    QString reference = QStringLiteral("vacuum");
    double vacuumWavelength_nm = kHeNeVacuumWavelength_nm;
};

struct PositionReading {
    double time_s = 0;
    double position_mm = 0;   ///< the interferometer's length since it was zeroed
    double deviation_um = 0;  ///< actual − target (ISO 230-2 sign), as read
};

struct EnvironmentReading {
    double time_s = 0;
    AirState air;  ///< CO2 is not streamed: the default applies
    std::optional<double>
        material_C;  ///< carried, not used to correct (see EnvironmentCorrection.h)
};

struct InterferometerLine {
    enum class Kind { Ignored, Header, Environment, Position, End };
    Kind kind = Kind::Ignored;
    InterferometerHeader header;
    EnvironmentReading environment;
    PositionReading position;
};

/// A line that is not the protocol: what() reads "line 7, pressure_Pa: …".
class InterferometerLineError : public std::runtime_error {
public:
    InterferometerLineError(int line, const QString& field, const QString& message);
    int line() const { return m_line; }
    const QString& field() const { return m_field; }
    const QString& message() const { return m_message; }

private:
    int m_line;
    QString m_field;
    QString m_message;
};

/// Parses the lines of one stream in order; keeps what the protocol's order needs.
class InterferometerLineParser {
public:
    /// One line without its line break (a trailing '\r' is dropped). Throws
    /// InterferometerLineError.
    InterferometerLine parse(std::string_view text);
    /// Number of the line parsed last (1-based).
    int lineNumber() const { return m_line; }
    const std::optional<InterferometerHeader>& header() const { return m_header; }
    bool ended() const { return m_ended; }

private:
    [[noreturn]] void fail(const QString& field, const QString& message) const;
    double number(std::string_view text, const QString& field) const;
    InterferometerHeader parseHeader(std::string_view text) const;
    void checkTime(double time_s, const QString& field);

    int m_line = 0;
    std::optional<InterferometerHeader> m_header;
    bool m_ended = false;
    std::optional<double> m_lastTime_s;
};

}  // namespace driftlab::interferometer
