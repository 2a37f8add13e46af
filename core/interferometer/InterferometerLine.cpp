#include "core/interferometer/InterferometerLine.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "core/bundle/ValueLimits.h"
#include "core/domain/MessageText.h"

namespace driftlab::interferometer {
namespace {

/// Beyond 100 m no feed axis reaches: a position in µm given as mm.
constexpr double kMaxPositionMm = 100'000.0;

std::vector<std::string_view> split(std::string_view text) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string_view field = text.substr(start, comma == text.npos ? text.npos : comma - start);
        while (!field.empty() && (field.front() == ' ' || field.front() == '\t'))
            field.remove_prefix(1);
        while (!field.empty() && (field.back() == ' ' || field.back() == '\t'))
            field.remove_suffix(1);
        fields.push_back(field);
        if (comma == text.npos) return fields;
        start = comma + 1;
    }
}

QString qs(std::string_view text) {
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

}  // namespace

InterferometerLineError::InterferometerLineError(int line, const QString& field,
                                                 const QString& message)
    : std::runtime_error((field.isEmpty()
                              ? QStringLiteral("line %1: %2").arg(line).arg(message)
                              : QStringLiteral("line %1, %2: %3").arg(line).arg(field, message))
                             .toStdString()),
      m_line(line),
      m_field(field),
      m_message(message) {}

void InterferometerLineParser::fail(const QString& field, const QString& message) const {
    throw InterferometerLineError(m_line, field, message);
}

double InterferometerLineParser::number(std::string_view text, const QString& field) const {
    if (text.empty()) fail(field, QStringLiteral("empty field"));
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        fail(field, QStringLiteral("'%1' is not a number").arg(qs(text)));
    // from_chars reads "nan" and "inf": a sensor that lost its reading, not a value.
    if (!std::isfinite(value)) fail(field, QStringLiteral("NaN or infinite value"));
    return value;
}

void InterferometerLineParser::checkTime(double time_s, const QString& field) {
    if (const auto problem = bundle::impossibleTime(time_s)) fail(field, *problem);
    if (m_lastTime_s && time_s < *m_lastTime_s)
        fail(field, QStringLiteral("time goes back from %1 s to %2 s")
                        .arg(numberText(*m_lastTime_s), numberText(time_s)));
    m_lastTime_s = time_s;
}

InterferometerHeader InterferometerLineParser::parseHeader(std::string_view text) const {
    InterferometerHeader header;
    bool sawCompensation = false;
    const auto fields = split(text);
    for (std::size_t i = 1; i < fields.size(); ++i) {
        const std::size_t eq = fields[i].find('=');
        if (eq == std::string_view::npos)
            fail(QStringLiteral("header"),
                 QStringLiteral("'%1' is not key=value").arg(qs(fields[i])));
        const std::string_view key = fields[i].substr(0, eq), value = fields[i].substr(eq + 1);
        const QString field = qs(key);
        if (key == "compensation") {
            if (value != "on" && value != "off")
                fail(field, QStringLiteral("'%1' is neither on nor off").arg(qs(value)));
            header.compensationOn = value == "on";
            sawCompensation = true;
        } else if (key == "reference") {
            header.reference = qs(value);
            if (value == "vacuum") {
                header.assumedIndex = 1.0;
            } else if (value == "standard-air") {
                header.assumedIndex = -1;  // resolved below, once the wavelength is known
            } else {
                header.assumedIndex = number(value, field);
                if (header.assumedIndex < 1.0 || header.assumedIndex >= 1.001)
                    fail(field, QStringLiteral("%1 is not a refractive index of air or vacuum "
                                               "(vacuum, standard-air or 1…1.001)")
                                    .arg(qs(value)));
            }
        } else if (key == "wavelength_nm") {
            header.vacuumWavelength_nm = number(value, field);
            if (header.vacuumWavelength_nm < 300 || header.vacuumWavelength_nm > 1700)
                fail(field, QStringLiteral("%1 nm is outside 300…1700 nm%2")
                                .arg(qs(value))
                                .arg(header.vacuumWavelength_nm < 2
                                         ? QStringLiteral(" (µm? DriftLab expects nm)")
                                         : QString()));
        } else {
            fail(field, QStringLiteral("unknown header key (compensation, reference, "
                                       "wavelength_nm)"));
        }
    }
    if (!sawCompensation)
        fail(QStringLiteral("header"), QStringLiteral("compensation=on|off is missing"));
    if (header.assumedIndex < 0)
        header.assumedIndex = edlenRefractiveIndex(AirState{20.0, 101'325.0, 50.0, 450.0},
                                                   header.vacuumWavelength_nm);
    return header;
}

InterferometerLine InterferometerLineParser::parse(std::string_view text) {
    ++m_line;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    InterferometerLine line;
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == text.npos || text[first] == '#') return line;
    if (m_ended) fail({}, QStringLiteral("a line after 'end'"));

    const auto fields = split(text);
    if (fields[0] == "header") {
        if (m_header) fail({}, QStringLiteral("a second header line"));
        line.kind = InterferometerLine::Kind::Header;
        line.header = parseHeader(text);
        m_header = line.header;
        return line;
    }
    if (!m_header)
        fail({}, QStringLiteral("data before the header line "
                                "('header,compensation=on|off' comes first)"));
    if (fields[0] == "end") {
        if (fields.size() != 1) fail({}, QStringLiteral("'end' takes no fields"));
        line.kind = InterferometerLine::Kind::End;
        m_ended = true;
        return line;
    }
    if (fields[0] == "env") {
        if (fields.size() != 5 && fields.size() != 6)
            fail({}, QStringLiteral("env line has %1 fields; expected "
                                    "env,time_s,air_C,pressure_Pa,humidity_pct[,material_C]")
                         .arg(fields.size()));
        EnvironmentReading& env = line.environment;
        env.time_s = number(fields[1], QStringLiteral("time_s"));
        env.air.temperature_C = number(fields[2], QStringLiteral("air_C"));
        env.air.pressure_Pa = number(fields[3], QStringLiteral("pressure_Pa"));
        env.air.humidity_pct = number(fields[4], QStringLiteral("humidity_pct"));
        if (fields.size() == 6) {
            env.material_C = number(fields[5], QStringLiteral("material_C"));
            if (const auto problem =
                    bundle::impossibleValue(Quantity::Temperature, *env.material_C))
                fail(QStringLiteral("material_C"), *problem);
        }
        // Name the field the range problem is in: check one quantity at a time.
        const AirState nominal;
        const struct {
            const char* field;
            AirState probe;
        } checks[] = {
            {"air_C", AirState{env.air.temperature_C, nominal.pressure_Pa, nominal.humidity_pct}},
            {"pressure_Pa",
             AirState{nominal.temperature_C, env.air.pressure_Pa, nominal.humidity_pct}},
            {"humidity_pct",
             AirState{nominal.temperature_C, nominal.pressure_Pa, env.air.humidity_pct}},
        };
        for (const auto& check : checks)
            if (const auto problem = airStateProblem(check.probe))
                fail(QString::fromLatin1(check.field), *problem);
        checkTime(env.time_s, QStringLiteral("time_s"));
        line.kind = InterferometerLine::Kind::Environment;
        return line;
    }
    if (fields.size() != 3)
        fail({}, QStringLiteral("%1 fields; a reading is time_s,position_mm,deviation_um "
                                "(or a line starting with header, env or end)")
                     .arg(fields.size()));
    PositionReading& r = line.position;
    r.time_s = number(fields[0], QStringLiteral("time_s"));
    r.position_mm = number(fields[1], QStringLiteral("position_mm"));
    r.deviation_um = number(fields[2], QStringLiteral("deviation_um"));
    if (std::abs(r.position_mm) > kMaxPositionMm)
        fail(QStringLiteral("position_mm"),
             QStringLiteral("%1 mm is beyond ±%2 mm (µm instead of mm?)")
                 .arg(numberText(r.position_mm), numberText(kMaxPositionMm)));
    if (const auto problem = bundle::impossibleDeviation(r.deviation_um))
        fail(QStringLiteral("deviation_um"), *problem);
    checkTime(r.time_s, QStringLiteral("time_s"));
    line.kind = InterferometerLine::Kind::Position;
    return line;
}

}  // namespace driftlab::interferometer
