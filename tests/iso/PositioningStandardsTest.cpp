// The positioning standards side by side, on the hand-worked G1 readings
// (Iso230TestData.h: 3 targets × 2 directions × 5 cycles, s and x̄ exact) and
// on one target where JIS B 0182 and ISO 230-2 take different terms of R.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/iso/PositioningStandards.h"
#include "tests/iso/Iso230TestData.h"

namespace driftlab::iso {
// Named, not anonymous: the unity build puts the ISO tests in one file.
namespace standards_test {

using test::add;
using test::golden3x5;

constexpr double kExact = 1e-12;

StandardEvaluation evaluateOk(const std::vector<Reading>& readings, PositioningStandard standard) {
    StandardEvaluation e = evaluateStandard(readings, standard);
    EXPECT_TRUE(e.ok()) << qPrintable(e.error);
    return e;
}

double valueOf(const StandardEvaluation& e, const char* key) {
    const StandardValue* v = e.value(QLatin1String(key));
    EXPECT_NE(v, nullptr) << qPrintable(standardTitle(e.standard)) << " has no " << key;
    return v ? v->value_um : std::nan("");
}

// G1 by ISO 230-2 with k = 2 (worked in Iso230TestData.h): B = 5, B̄ = 3,
// R↑ = 4, R↓ = 6, R = 9, E↑ = 5, E↓ = 7, E = 8, M = 6, A↑ = 6, A↓ = 12, A = 12.
const std::pair<const char*, double> kG1Iso[] = {
    {"B", 5},      {"B_mean", 3}, {"R_up", 4}, {"R_down", 6}, {"R", 9},       {"E_up", 5},
    {"E_down", 7}, {"E", 8},      {"M", 6},    {"A_up", 6},   {"A_down", 12}, {"A", 12}};

TEST(PositioningStandards, everyIsoEditionGivesTheHandWorkedGoldenValues) {
    for (PositioningStandard standard :
         {PositioningStandard::Iso230_2_2014, PositioningStandard::Iso230_2_2006,
          PositioningStandard::Iso230_2_1997}) {
        const StandardEvaluation e = evaluateOk(golden3x5(), standard);
        EXPECT_EQ(e.coverage_factor, 2);
        EXPECT_EQ(e.min_approaches, 5);
        EXPECT_EQ(e.values.size(), std::size(kG1Iso));
        for (const auto& [key, value] : kG1Iso)
            EXPECT_NEAR(valueOf(e, key), value, kExact)
                << qPrintable(standardTitle(standard)) << " " << key;
    }
}

TEST(PositioningStandards, gbt17421IsEvaluatedAsIso230_2Of2006) {
    // GB/T 17421.2-2016's scope is ISO 230-2:2006's: the same twelve values,
    // k = 2 and five approaches, so G1 gives the ISO golden values.
    const StandardEvaluation gb = evaluateOk(golden3x5(), PositioningStandard::GbT17421_2_2016);
    EXPECT_EQ(standardTitle(gb.standard), QStringLiteral("GB/T 17421.2-2016"));
    EXPECT_EQ(gb.coverage_factor, 2);
    EXPECT_EQ(gb.min_approaches, 5);
    EXPECT_TRUE(gb.definitions.contains(QStringLiteral("ISO 230-2:2006")));
    for (const auto& [key, value] : kG1Iso) EXPECT_NEAR(valueOf(gb, key), value, kExact) << key;
}

TEST(PositioningStandards, jisB0182RepeatabilityTakesThreeStandardDeviations) {
    // G1 by JIS B 0182 (k = 3): R_i = max(3s↑ + 3s↓ + |B_i|, 6s↑, 6s↓).
    //   0 mm    s↑ = 1,   s↓ = 1,   B = 5:  3 + 3 + 5 = 11, 6, 6      → 11
    //   100 mm  s↑ = 0.5, s↓ = 1.5, B = 1:  1.5 + 4.5 + 1 = 7, 3, 9   → 9
    //   200 mm  s↑ = 0,   s↓ = 1,   B = 3:  0 + 3 + 3 = 6, 0, 6       → 6
    // R = 11 where ISO's k = 2 gives 2 + 2 + 5 = 9; B = largest |B_i| = 5 in both.
    const StandardEvaluation jis = evaluateOk(golden3x5(), PositioningStandard::JisB0182_1993);
    EXPECT_EQ(jis.coverage_factor, 3);
    EXPECT_EQ(jis.min_approaches, 0);
    ASSERT_EQ(jis.values.size(), 2u);
    EXPECT_NEAR(valueOf(jis, "B"), 5, kExact);
    EXPECT_NEAR(valueOf(jis, "R"), 11, kExact);
    // The vocabulary defines no accuracy, systematic error or mean reversal.
    for (const char* key : {"A", "E", "M", "B_mean", "R_up"})
        EXPECT_EQ(jis.value(QLatin1String(key)), nullptr) << key;
    const StandardEvaluation iso = evaluateOk(golden3x5(), PositioningStandard::Iso230_2_2014);
    EXPECT_NEAR(valueOf(iso, "R"), 9, kExact);
}

TEST(PositioningStandards, jisRepeatabilityIsTheBackwardTermWhereIsoTakesTheBidirectional) {
    // One target where the two standards pick different terms of R_i, so that
    // JIS's R is not ISO's scaled by 3/2 (k = 3 against k = 2). At 0 mm: ↑ 2, 3, 2.5, 3, 2 (x̄↑
    // = 2.5, s↑ = 0.5), ↓ −1.5, 1.5, 0, 1.5, −1.5 (x̄↓ = 0, s↓ = sqrt(4·1.5²/4) = 1.5), B = 2.5. At
    // 100 mm every reading is 0: R_100 = 0.
    //   ISO, k = 2: 2·0.5 + 2·1.5 + 2.5 = 6.5 > 4s↓ = 6 > 4s↑ = 2  → R = 6.5
    //   JIS, k = 3: 3·0.5 + 3·1.5 + 2.5 = 8.5 < 6s↓ = 9             → R = 9
    // The bidirectional term adds k·(s↑ + s↓) to |B|, the backward one is
    // 2k·s↓: their gap k·(s↑ − s↓) + |B| = −k + 2.5 changes sign between k = 2
    // and k = 3.
    std::vector<Reading> r;
    add(r, 0, Direction::Positive, {2, 3, 2.5, 3, 2});
    add(r, 0, Direction::Negative, {-1.5, 1.5, 0, 1.5, -1.5});
    add(r, 100, Direction::Positive, {0, 0, 0, 0, 0});
    add(r, 100, Direction::Negative, {0, 0, 0, 0, 0});
    const StandardEvaluation iso = evaluateOk(r, PositioningStandard::Iso230_2_2014);
    const StandardEvaluation jis = evaluateOk(r, PositioningStandard::JisB0182_1993);
    EXPECT_NEAR(valueOf(iso, "R"), 6.5, kExact);
    EXPECT_NEAR(valueOf(iso, "R_down"), 6, kExact);
    EXPECT_NEAR(valueOf(jis, "R"), 9, kExact);
    // JIS's R is 6s↓ = 3/2 of ISO's R↓ = 4s↓, not 3/2 of ISO's R (9.75).
    EXPECT_NEAR(valueOf(jis, "R"), 1.5 * valueOf(iso, "R_down"), kExact);
    EXPECT_LT(valueOf(jis, "R"), 1.5 * valueOf(iso, "R"));
    EXPECT_NEAR(valueOf(jis, "B"), 2.5, kExact);
    EXPECT_NEAR(valueOf(iso, "B"), 2.5, kExact);
}

TEST(PositioningStandards, onlyIsoBasedStandardsWarnAboutIsoMinimums) {
    // G1 has three targets, below ISO 230-2's five: a warning for ISO and
    // GB/T, none for the JIS vocabulary, which states no minimum. The swing
    // common to every target is about the data and is warned about by all.
    const auto minimum = [](const QStringList& warnings) {
        for (const QString& w : warnings)
            if (w.startsWith(QStringLiteral("below ISO 230-2's minimum"))) return true;
        return false;
    };
    const auto drift = [](const QStringList& warnings) {
        for (const QString& w : warnings)
            if (w.startsWith(QStringLiteral("deviations drift"))) return true;
        return false;
    };
    for (PositioningStandard standard : positioningStandards()) {
        const StandardEvaluation e = evaluateOk(golden3x5(), standard);
        EXPECT_EQ(minimum(e.warnings), standard != PositioningStandard::JisB0182_1993)
            << qPrintable(standardTitle(standard));
        EXPECT_TRUE(drift(e.warnings)) << qPrintable(standardTitle(standard));
    }
}

TEST(PositioningStandards, comparisonEvaluatesEveryStandardAndWarnsOnce) {
    const StandardsComparison c = compareStandards(golden3x5());
    ASSERT_TRUE(c.ok()) << qPrintable(c.error);
    ASSERT_EQ(c.evaluations.size(), positioningStandards().size());
    for (std::size_t i = 0; i < c.evaluations.size(); ++i) {
        EXPECT_EQ(c.evaluations[i].standard, positioningStandards()[i]);
        EXPECT_EQ(c.evaluations[i].targets, 3);
        EXPECT_EQ(c.evaluations[i].cycles, 5);
    }
    // A table row per key, each once: ISO 230-2's twelve, in its order; JIS's
    // B and R are among them.
    QStringList keys;
    for (const StandardValue* row : comparisonRows(c)) keys << row->key;
    EXPECT_EQ(keys, (QStringList{"B", "B_mean", "R_up", "R_down", "R", "E_up", "E_down", "E", "M",
                                 "A_up", "A_down", "A"}));
    // Two distinct warnings (three targets; the common swing), however many
    // standards raise them.
    EXPECT_EQ(c.warnings.size(), 2) << qPrintable(c.warnings.join(QLatin1Char('\n')));
}

TEST(PositioningStandards, comparisonNamesTheStandardThatRefusesTheReadings) {
    std::vector<Reading> oneTarget;
    add(oneTarget, 10, Direction::Positive, {1, 2});
    add(oneTarget, 10, Direction::Negative, {1, 2});
    const StandardsComparison c = compareStandards(oneTarget);
    EXPECT_FALSE(c.ok());
    EXPECT_TRUE(c.error.startsWith(QStringLiteral("ISO 230-2:2014: one target")))
        << qPrintable(c.error);
}

TEST(PositioningStandards, longAxisSingleApproachLeavesJisRepeatabilityUndetermined) {
    // G2: 2500 mm, one approach per direction: B = 2 (|B_0| = |B_2500| = 2),
    // R cannot be estimated without s.
    const StandardEvaluation jis =
        evaluateOk(test::longAxisSingleApproach(), PositioningStandard::JisB0182_1993);
    EXPECT_NEAR(valueOf(jis, "B"), 2, kExact);
    EXPECT_TRUE(std::isnan(valueOf(jis, "R")));
    ASSERT_EQ(jis.skipped.size(), 1);
    EXPECT_TRUE(jis.skipped.front().startsWith(QStringLiteral("R not determined")));
}

TEST(PositioningStandards, idsNameOneStandardEachAndLeftOutOnesAreNotEvaluated) {
    std::set<QString> ids;
    for (PositioningStandard standard : positioningStandards()) {
        const QString id = standardId(standard);
        EXPECT_TRUE(ids.insert(id).second) << qPrintable(id);
        EXPECT_EQ(standardFromId(id), standard);
        EXPECT_EQ(standardFromId(id.toUpper()), standard);
        EXPECT_EQ(leftOutStandard(id), nullptr);
    }
    EXPECT_EQ(standardFromId(QStringLiteral("iso230-2:1988")), std::nullopt);
    for (const char* id : {"vdi3441", "asme-b5.54", "jis-b6192"}) {
        const LeftOutStandard* left = leftOutStandard(QLatin1String(id));
        ASSERT_NE(left, nullptr) << id;
        EXPECT_FALSE(left->why.isEmpty()) << id;
        EXPECT_EQ(standardFromId(QLatin1String(id)), std::nullopt) << id;
        EXPECT_TRUE(ids.insert(left->id).second) << id;
    }
}

}  // namespace standards_test
}  // namespace driftlab::iso
