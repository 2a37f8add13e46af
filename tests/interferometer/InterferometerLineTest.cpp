// The line protocol of docs/interferometer.md: what it accepts, and that every
// refusal names the line and the field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/interferometer/InterferometerSession.h"

using namespace driftlab;

namespace {

/// Feeds `lines`; the error's text, or empty when all were accepted.
std::string firstError(const std::vector<std::string>& lines) {
    interferometer::InterferometerSession session;
    try {
        for (const auto& line : lines) session.feed(line);
    } catch (const interferometer::InterferometerLineError& e) {
        return e.what();
    }
    return {};
}

const std::string kOff = "header,compensation=off,reference=vacuum";
const std::string kOn = "header,compensation=on";

}  // namespace

TEST(InterferometerLine, readsHeaderEnvironmentReadingsCommentsAndEnd) {
    interferometer::InterferometerLineParser parser;
    EXPECT_EQ(parser.parse("# DriftLab interferometer stream").kind,
              interferometer::InterferometerLine::Kind::Ignored);
    const auto header = parser.parse(
        "header,compensation=off,reference=standard-air,"
        "wavelength_nm=632.991\r");
    ASSERT_EQ(header.kind, interferometer::InterferometerLine::Kind::Header);
    EXPECT_FALSE(header.header.compensationOn);
    EXPECT_DOUBLE_EQ(header.header.assumedIndex, interferometer::standardAirIndex());
    EXPECT_EQ(parser.parse("").kind, interferometer::InterferometerLine::Kind::Ignored);
    const auto env = parser.parse("env,0.5,20.25,100900,41.5,20.8");
    ASSERT_EQ(env.kind, interferometer::InterferometerLine::Kind::Environment);
    EXPECT_EQ(env.environment.air.temperature_C, 20.25);
    EXPECT_EQ(env.environment.air.pressure_Pa, 100900);
    EXPECT_EQ(env.environment.air.humidity_pct, 41.5);
    EXPECT_EQ(env.environment.material_C, 20.8);
    const auto reading = parser.parse("1.5, 250.0005, -3.25");
    ASSERT_EQ(reading.kind, interferometer::InterferometerLine::Kind::Position);
    EXPECT_EQ(reading.position.time_s, 1.5);
    EXPECT_EQ(reading.position.position_mm, 250.0005);
    EXPECT_EQ(reading.position.deviation_um, -3.25);
    EXPECT_EQ(parser.parse("end").kind, interferometer::InterferometerLine::Kind::End);
    EXPECT_TRUE(parser.ended());
    EXPECT_EQ(parser.lineNumber(), 6);
}

TEST(InterferometerLine, headerComesFirstOnceAndComplete) {
    EXPECT_EQ(firstError({"# c", "0,0,0"}),
              "line 2: data before the header line ('header,compensation=on|off' comes first)");
    EXPECT_EQ(firstError({"header,reference=vacuum"}),
              "line 1, header: compensation=on|off is missing");
    EXPECT_EQ(firstError({"header,compensation=maybe"}),
              "line 1, compensation: 'maybe' is neither on nor off");
    EXPECT_EQ(firstError({kOn, kOn}), "line 2: a second header line");
    EXPECT_EQ(firstError({"header,compensation=on,speed=3"}),
              "line 1, speed: unknown header key (compensation, reference, wavelength_nm)");
    EXPECT_EQ(firstError({"header,compensation=off,wavelength_nm=0.633"}),
              "line 1, wavelength_nm: 0.633 nm is outside 300…1700 nm (µm? DriftLab expects nm)");
}

TEST(InterferometerLine, refusesNanJunkAndWrongFieldCounts) {
    EXPECT_EQ(firstError({kOn, "1,nan,0"}), "line 2, position_mm: NaN or infinite value");
    EXPECT_EQ(firstError({kOn, "1,2,inf"}), "line 2, deviation_um: NaN or infinite value");
    EXPECT_EQ(firstError({kOn, "1,2.5mm,0"}), "line 2, position_mm: '2.5mm' is not a number");
    EXPECT_EQ(firstError({kOn, "1,,0"}), "line 2, position_mm: empty field");
    EXPECT_EQ(firstError({kOn, "1,2"}),
              "line 2: 2 fields; a reading is time_s,position_mm,deviation_um (or a line "
              "starting with header, env or end)");
    EXPECT_EQ(firstError({kOn, "env,1,20,101325"}),
              "line 2: env line has 4 fields; expected "
              "env,time_s,air_C,pressure_Pa,humidity_pct[,material_C]");
    EXPECT_EQ(firstError({kOn, "end", "1,2,3"}), "line 3: a line after 'end'");
}

TEST(InterferometerLine, unitMixUpsAreNamed) {
    EXPECT_EQ(firstError({kOff, "env,0,20,1013.25,50"}),
              "line 2, pressure_Pa: air pressure 1013.25 Pa is outside 60000…120000 Pa "
              "(hPa? DriftLab expects Pa)");
    EXPECT_EQ(firstError({kOff, "env,0,20,101.3,50"}),
              "line 2, pressure_Pa: air pressure 101.3 Pa is outside 60000…120000 Pa "
              "(kPa? DriftLab expects Pa)");
    EXPECT_EQ(firstError({kOff, "env,0,293.4,101300,50"}),
              "line 2, air_C: air temperature 293.4 °C is outside −10…50 °C (kelvin? "
              "DriftLab expects °C)");
    EXPECT_EQ(firstError({kOff, "env,0,20,101300,150"}),
              "line 2, humidity_pct: relative humidity 150 % is outside 0…100 %");
    EXPECT_EQ(firstError({kOn, "1,250000,0"}),
              "line 2, position_mm: 250000 mm is beyond ±100000 mm (µm instead of mm?)");
    EXPECT_EQ(firstError({kOn, "1,250,35000"}),
              "line 2, deviation_um: 35000 µm is beyond ±10000 µm for a positioning deviation "
              "(nm instead of µm?)");
    EXPECT_EQ(firstError({kOn, "5,1,0", "4,2,0"}),
              "line 3, time_s: time goes back from 5 s to 4 s");
}

TEST(InterferometerSession, compensationOffCorrectsWithTheLatestAir) {
    interferometer::InterferometerSession session;
    EXPECT_FALSE(session.feed(kOff));
    EXPECT_FALSE(session.feed("env,0,20,101325,50"));
    const auto first = session.feed("1,500,2.0");
    ASSERT_TRUE(first);
    const double n1 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{20, 101'325, 50});
    EXPECT_NEAR(first->position_mm, 500.0 / n1, 1e-12);
    EXPECT_NEAR(first->deviation_um, 2.0 + 500.0 * 1000.0 * (1.0 / n1 - 1.0), 1e-7);
    EXPECT_EQ(first->line, 3);
    EXPECT_TRUE(first->correction.description.startsWith(QStringLiteral("Edlén, 20.0 °C")));

    EXPECT_FALSE(session.feed("env,2,22,99000,30"));
    const auto second = session.feed("3,500,2.0");
    ASSERT_TRUE(second);
    const double n2 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{22, 99'000, 30});
    EXPECT_NEAR(second->position_mm, 500.0 / n2, 1e-12);
    EXPECT_EQ(second->reading.position_mm, 500.0);
}

TEST(InterferometerSession, compensationOnKeepsTheReadingAndSaysSo) {
    interferometer::InterferometerSession session;
    session.feed(kOn);
    session.feed("env,0,25,95000,60");  // recorded, not applied
    const auto r = session.feed("1,500,2.0");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->position_mm, 500.0);
    EXPECT_EQ(r->deviation_um, 2.0);
    EXPECT_EQ(r->correction.description,
              QStringLiteral("none: the interferometer compensated itself"));
    ASSERT_TRUE(session.lastEnvironment());
    EXPECT_EQ(session.lastEnvironment()->air.temperature_C, 25.0);
}

TEST(InterferometerSession, compensationOffRefusesReadingsWithoutFreshAir) {
    EXPECT_EQ(firstError({kOff, "1,500,2"}),
              "line 2: a reading before any env line: with compensation=off DriftLab needs the "
              "air temperature, pressure and humidity to correct it");
    EXPECT_EQ(firstError({kOff, "env,0,20,101325,50", "# later", "400,500,2"}),
              "line 4, time_s: the latest env line (line 2) is 400 s old (limit 300 s): the air "
              "is stale");
}
