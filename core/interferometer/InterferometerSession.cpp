#include "core/interferometer/InterferometerSession.h"

namespace driftlab::interferometer {

std::optional<CorrectedReading> InterferometerSession::feed(std::string_view text) {
    const InterferometerLine line = m_parser.parse(text);
    const int number = m_parser.lineNumber();
    switch (line.kind) {
        case InterferometerLine::Kind::Ignored:
        case InterferometerLine::Kind::Header:
        case InterferometerLine::Kind::End:
            return std::nullopt;
        case InterferometerLine::Kind::Environment: {
            m_environment = line.environment;
            m_environmentLine = number;
            const InterferometerHeader& header = *m_parser.header();
            // The parser has range-checked the air, so this does not throw.
            m_correction = header.compensationOn
                               ? noCorrection()
                               : edlenCorrection(line.environment.air, header.assumedIndex,
                                                 header.vacuumWavelength_nm);
            return std::nullopt;
        }
        case InterferometerLine::Kind::Position:
            break;
    }
    CorrectedReading out;
    out.line = number;
    out.reading = line.position;
    if (m_parser.header()->compensationOn) {
        out.correction = noCorrection();
    } else {
        if (!m_environment)
            throw InterferometerLineError(
                number, {},
                QStringLiteral("a reading before any env line: with compensation=off DriftLab "
                               "needs the air temperature, pressure and humidity to correct it"));
        const double age_s = line.position.time_s - m_environment->time_s;
        if (age_s > m_maxEnvironmentAge_s)
            throw InterferometerLineError(
                number, QStringLiteral("time_s"),
                QStringLiteral("the latest env line (line %1) is %2 s old (limit %3 s): the "
                               "air is stale")
                    .arg(m_environmentLine)
                    .arg(age_s, 0, 'g', 6)
                    .arg(m_maxEnvironmentAge_s, 0, 'g', 6));
        out.correction = m_correction;
    }
    out.position_mm = out.correction.correctedLength_mm(line.position.position_mm);
    out.deviation_um =
        out.correction.correctedDeviation_um(line.position.position_mm, line.position.deviation_um);
    return out;
}

}  // namespace driftlab::interferometer
