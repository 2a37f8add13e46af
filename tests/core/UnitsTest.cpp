// The one unit rule of a bundle's header and a device map: DriftLab's unit in
// its spellings as it is, °F and K into °C by the exact formulas, anything
// else refused with the unit and the units DriftLab reads named.
#include <gtest/gtest.h>

#include "core/domain/Units.h"

using namespace driftlab;

namespace {

UnitConversion known(Quantity quantity, const char* unit) {
    QString why;
    const auto conversion = conversionToDriftLabUnit(quantity, QString::fromUtf8(unit), &why);
    EXPECT_TRUE(conversion) << unit << ": " << qPrintable(why);
    return conversion.value_or(UnitConversion{});
}

QString refused(Quantity quantity, const char* unit) {
    QString why;
    EXPECT_FALSE(conversionToDriftLabUnit(quantity, QString::fromUtf8(unit), &why)) << unit;
    return why;
}

}  // namespace

TEST(UnitRule, driftLabsOwnUnitsInTheirSpellingsAreTakenAsTheyAre) {
    for (const char* unit : {"°C", "degC", "deg C", "C", "℃", "Celsius"})
        EXPECT_TRUE(known(Quantity::Temperature, unit).isIdentity()) << unit;
    for (const char* unit : {"µm", "μm", "um", "microns"})
        EXPECT_TRUE(known(Quantity::Displacement, unit).isIdentity()) << unit;
    for (const char* unit : {"rpm", "1/min"})
        EXPECT_TRUE(known(Quantity::Speed, unit).isIdentity()) << unit;
    EXPECT_EQ(known(Quantity::Temperature, "°C").apply(-0.1), -0.1);
}

TEST(UnitRule, fahrenheitAndKelvinBecomeCelsiusExactly) {
    const UnitConversion f = known(Quantity::Temperature, "°F");
    EXPECT_EQ(f.from, QStringLiteral("°F"));
    EXPECT_EQ(f.apply(32.0), 0.0);
    EXPECT_EQ(f.apply(212.0), 100.0);
    EXPECT_EQ(f.apply(-40.0), -40.0);
    EXPECT_EQ(f.apply(68.9), (68.9 - 32.0) * 5.0 / 9.0);
    EXPECT_FALSE(f.isIdentity());
    EXPECT_EQ(known(Quantity::Temperature, "degF").apply(50.0), 10.0);
    const UnitConversion k = known(Quantity::Temperature, "K");
    EXPECT_EQ(k.apply(273.15), 0.0);
    EXPECT_EQ(k.apply(294.65), 294.65 - 273.15);
    EXPECT_EQ(known(Quantity::Temperature, "kelvin").apply(373.15), 373.15 - 273.15);
}

TEST(UnitRule, anythingElseIsRefusedNamingTheUnitAndTheUnitsRead) {
    EXPECT_EQ(refused(Quantity::Temperature, "mV"),
              QStringLiteral("'mV' is not a unit DriftLab reads for a temperature channel "
                             "(°C, °F or K)"));
    EXPECT_EQ(refused(Quantity::Temperature, "°R"),
              QStringLiteral("'°R' is not a unit DriftLab reads for a temperature channel "
                             "(°C, °F or K)"));
    // Only temperatures are converted: a displacement in mm is a unit mix-up.
    EXPECT_EQ(refused(Quantity::Displacement, "mm"),
              QStringLiteral("'mm' is not a unit DriftLab reads for a displacement channel (µm)"));
    EXPECT_EQ(refused(Quantity::Speed, "Hz"),
              QStringLiteral("'Hz' is not a unit DriftLab reads for a speed channel (rpm)"));
}
