// Acceptance as a calibration lab signs it: the uncertainty budget of a worked
// example, the 20 °C normalisation against its closed form, the decision rule
// of ISO 14253-1 at its edges, the environmental variation error from an ETVE
// run, and the specification file's errors.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QTemporaryDir>
#include <cmath>

#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/ConformanceDecision.h"
#include "core/iso/DriftAcceptance.h"
#include "core/iso/MeasurementUncertainty.h"
#include "core/iso/PositioningAcceptance.h"
#include "core/iso/ReferenceTemperature.h"

namespace driftlab::iso {
namespace {

const double kSqrt3 = std::sqrt(3.0);

// --- the uncertainty budget ---------------------------------------------------

TEST(EdlenSensitivities, matchThePublishedValuesAtTwentyDegrees) {
    // Near 20 °C, 101325 Pa, 50 %RH a HeNe interferometer's length changes by
    // about 0.93 ppm per K of air, 0.27 ppm per hPa, 0.0085 ppm per %RH.
    const EdlenSensitivities s = edlenSensitivities({});
    EXPECT_NEAR(s.per_K * 1e6, 0.93, 0.03);
    EXPECT_NEAR(s.per_hPa * 1e6, 0.268, 0.008);
    EXPECT_NEAR(s.per_pct * 1e6, 0.0085, 0.0008);
}

/// The worked example: a 500 mm travel measured at 23 °C material temperature.
SetupUncertainty workedSetup() {
    SetupUncertainty u;
    u.device_um = 0.2;
    u.device_ppm = 0.5;
    u.device_k = 2;
    u.air_temperature_K = 0.2;
    u.air_pressure_hPa = 1;
    u.air_humidity_pct = 10;
    u.material_temperature_K = 0.1;
    u.expansion_per_K = 1e-6;
    u.misalignment_mm = 0.5;
    return u;
}

UncertaintyConditions workedConditions() {
    UncertaintyConditions c;
    c.length_mm = 500;
    c.expansion_per_K = 11.5e-6;
    c.material_temperature_C = 23;
    c.eve_um = 2;
    c.eve_source = QStringLiteral("a test");
    return c;
}

TEST(UncertaintyBudget, workedExampleByHand) {
    const UncertaintyBudget budget = uncertaintyBudget(workedSetup(), workedConditions());
    const auto u = [&budget](const char* key) {
        return budget.contribution(QLatin1String(key))->standard_um;
    };
    // device: (0.2 µm + 0.5 µm/m · 0.5 m) / 2 = 0.225 µm
    EXPECT_NEAR(u("device"), 0.225, 1e-12);
    EXPECT_NEAR(u("device_at_target"), 0.1, 1e-12);
    // environment: 0.5 m · √((0.93·0.2)² + (0.268·1)² + (0.0085·10)²)/√3 ppm
    //            = 0.5 · √(0.034596 + 0.071824 + 0.007225)/1.7321 = 0.5 · 0.19463 = 0.0973 µm
    EXPECT_NEAR(u("environment"), 0.0973, 0.003);
    // machine temperature: 11.5e-6/K · 500 000 µm · 0.1 K/√3 = 0.33197 µm
    EXPECT_NEAR(u("material_temperature"), 5.75 * 0.1 / kSqrt3, 1e-9);
    EXPECT_NEAR(u("material_temperature"), 0.33197, 1e-5);
    // expansion coefficient: 500 000 µm · 3 K · 1e-6/K / √3 = 0.86603 µm
    EXPECT_NEAR(u("expansion"), 0.86603, 1e-5);
    // misalignment: φ = atan(0.5/500), e = 500 000 · (1 − cos φ) = 0.25 µm, u = e/(2√3)
    EXPECT_NEAR(u("misalignment"), 0.25 / (2 * kSqrt3), 1e-6);
    // EVE: 2 µm/(2√3) = 0.57735 µm
    EXPECT_NEAR(u("eve"), 0.57735, 1e-5);

    // E: √(0.225² + 0.0973² + 0.33197² + 0.86603² + 0.072169² + 0.57735²)
    //  = √(0.050625 + 0.009467 + 0.110204 + 0.75 + 0.005208 + 0.333333) = 1.12198 µm
    const ParameterUncertainty* e = budget.find(QStringLiteral("E"));
    ASSERT_NE(e, nullptr);
    EXPECT_NEAR(e->combined_um, 1.12198, 0.002);
    EXPECT_NEAR(e->expanded_um, 2 * e->combined_um, 1e-12);
    // A and M span the travel as E does.
    EXPECT_DOUBLE_EQ(budget.find(QStringLiteral("A"))->expanded_um, e->expanded_um);
    EXPECT_DOUBLE_EQ(budget.find(QStringLiteral("M"))->expanded_um, e->expanded_um);
    // R and B: only the device's length-independent part and the EVE stay:
    // √(0.1² + 0.57735²) = 0.58595 µm, U = 1.17190 µm.
    EXPECT_NEAR(budget.find(QStringLiteral("R"))->expanded_um, 1.17190, 1e-5);
    EXPECT_NEAR(budget.find(QStringLiteral("B"))->expanded_um, 1.17190, 1e-5);
    EXPECT_TRUE(budget.notes.isEmpty()) << budget.notes.join(QLatin1Char('\n')).toStdString();
}

TEST(UncertaintyBudget, namesTheContributorsLeftAtZero) {
    SetupUncertainty setup;
    setup.device_um = 0.1;
    const UncertaintyBudget budget = uncertaintyBudget(setup, {});
    EXPECT_TRUE(budget.notes.join(QLatin1Char('\n')).contains(QStringLiteral("misalignment")));
    EXPECT_TRUE(budget.notes.join(QLatin1Char('\n')).contains(QStringLiteral("ETVE")));
}

// --- the decision rule --------------------------------------------------------

TEST(ConformanceDecision, followsIsoFourteen253AtTheEdges) {
    // T = 10 µm, U = 2 µm: the conformance zone ends at 8, the
    // non-conformance zone starts above 12.
    EXPECT_EQ(decide("A", 5, 2, 10).verdict, Verdict::Pass);
    EXPECT_EQ(decide("A", 8, 2, 10).verdict, Verdict::Pass);  // y + U = T
    EXPECT_DOUBLE_EQ(decide("A", 8, 2, 10).margin_um, 0);
    // Inside the tolerance, but not proven: the uncertainty reaches beyond it.
    EXPECT_EQ(decide("A", 9, 2, 10).verdict, Verdict::NotProven);
    EXPECT_DOUBLE_EQ(decide("A", 9, 2, 10).margin_um, -1);
    // Outside the tolerance, but not proven either.
    EXPECT_EQ(decide("A", 11, 2, 10).verdict, Verdict::NotProven);
    EXPECT_EQ(decide("A", 12, 2, 10).verdict, Verdict::NotProven);  // y − U = T
    EXPECT_EQ(decide("A", 12.5, 2, 10).verdict, Verdict::Fail);
    // Without uncertainty the rule is the tolerance alone.
    EXPECT_EQ(decide("A", 10, 0, 10).verdict, Verdict::Pass);
    EXPECT_EQ(decide("A", 10.001, 0, 10).verdict, Verdict::Fail);
    EXPECT_EQ(decide("A", std::nan(""), 2, 10).verdict, Verdict::NotDetermined);
}

// --- a campaign with a warm machine -------------------------------------------

constexpr double kAlpha = 11.5e-6;

/// The material temperature, rising 1 K per hour from 22 °C.
double materialAt(double t_s) {
    return 22 + t_s / 3600;
}

/// The machine's own error at 20 °C: what normalisation must recover.
double errorAt20C(double target_mm) {
    return 3 * std::sin(target_mm / 97.0);
}

/// 6 targets × 5 bidirectional cycles over 500 mm, a reading every 30 s,
/// each carrying the expansion of the scale at its time; T_bed logged every
/// 60 s (the readings fall between samples), air constant 20.5 °C.
Campaign warmCampaign() {
    Campaign c;
    c.name = QStringLiteral("warm");
    c.machine = {QStringLiteral("VMC"), QStringLiteral("X"), QString(), {}};
    Screw screw;
    screw.alpha_per_K = kAlpha;
    c.screw = screw;
    c.channels = {
        {QStringLiteral("T_bed"), Quantity::Temperature, ChannelRole::Structure, {}, {}, {}},
        {QStringLiteral("T_air"), Quantity::Temperature, ChannelRole::Air, {}, {}, {}}};
    Run run;
    run.id = QStringLiteral("P1");
    run.kind = RunKind::Positioning;
    const double targets[] = {0, 95, 210, 290, 405, 500};
    double t_s = 0;
    for (int cycle = 1; cycle <= 5; ++cycle)
        for (Direction d : {Direction::Positive, Direction::Negative})
            for (int i = 0; i < 6; ++i) {
                const double p = targets[d == Direction::Positive ? i : 5 - i];
                const double expansion_um = kAlpha * (materialAt(t_s) - 20) * p * 1000;
                const double scatter_um = 0.2 * ((cycle % 2) ? 1 : -1);
                run.positioning.push_back(
                    {t_s, cycle, p, d, errorAt20C(p) + expansion_um + scatter_um});
                t_s += 30;
            }
    run.samples.columns = {QStringLiteral("T_bed"), QStringLiteral("T_air")};
    run.samples.values.resize(2);
    for (double s = 0; s <= t_s + 60; s += 60) {
        run.samples.time_s.push_back(s);
        run.samples.values[0].push_back(materialAt(s));
        run.samples.values[1].push_back(20.5);
    }
    c.runs.push_back(run);
    return c;
}

TEST(ReferenceTemperature, normalisationRecoversTheErrorAtTwentyDegrees) {
    const Campaign c = warmCampaign();
    Normalisation n;
    QString error;
    const auto readings = readingsAt20C(c, c.runs[0], {}, {QStringLiteral("T_bed")}, &n, &error);
    ASSERT_TRUE(readings) << error.toStdString();
    EXPECT_EQ(n.mode, Normalisation::Mode::Normalised);
    // Temperature linear in time, interpolated linearly: the correction is exact.
    for (std::size_t i = 0; i < readings->size(); ++i) {
        const double scatter_um = 0.2 * ((c.runs[0].positioning[i].cycle % 2) ? 1 : -1);
        EXPECT_NEAR((*readings)[i].deviation_um, errorAt20C((*readings)[i].target_mm) + scatter_um,
                    1e-9);
    }
    // The largest correction is at 500 mm, the warmest time there the first
    // reading of the last − pass: reading 54, t = 1620 s, θ = 22.45 °C.
    EXPECT_NEAR(n.largest_correction_um, kAlpha * (materialAt(30.0 * 54) - 20) * 500 * 1000, 1e-9);
    // 60 readings every 30 s: their mean time is 885 s.
    EXPECT_NEAR(n.mean_material_C, materialAt(885), 1e-9);
}

TEST(ReferenceTemperature, machineCompensationLeavesTheReadingsAlone) {
    const Campaign c = warmCampaign();
    TemperatureSetting setting;
    setting.machine_compensates = true;
    setting.normalise = false;
    Normalisation n;
    QString error;
    const auto readings = readingsAt20C(c, c.runs[0], setting, {}, &n, &error);
    ASSERT_TRUE(readings);
    EXPECT_EQ(n.mode, Normalisation::Mode::MachineCompensates);
    EXPECT_DOUBLE_EQ((*readings)[7].deviation_um, c.runs[0].positioning[7].deviation_um);
    EXPECT_TRUE(n.description.contains(QStringLiteral("machine's own")));
}

TEST(ReferenceTemperature, normalisingWithoutAMaterialTemperatureIsRefused) {
    Campaign c = warmCampaign();
    c.runs[0].samples = {};
    QString error;
    EXPECT_FALSE(readingsAt20C(c, c.runs[0], {}, {QStringLiteral("T_bed")}, nullptr, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("material_temperature_C"))) << error.toStdString();
    TemperatureSetting declared;
    declared.material_temperature_C = 21;
    const auto readings = readingsAt20C(c, c.runs[0], declared, {}, nullptr, &error);
    ASSERT_TRUE(readings);
    // At 21 °C and 500 mm: 11.5e-6 · 1 K · 500 000 µm = 5.75 µm taken out.
    const auto& last = c.runs[0].positioning.back();
    EXPECT_NEAR(readings->back().deviation_um, last.deviation_um - 5.75 * last.target_mm / 500,
                1e-9);
}

TEST(ReferenceTemperature, environmentSummaryStatesStartEndMinMaxMean) {
    const Campaign c = warmCampaign();
    const TestEnvironment env = testEnvironment(c, c.runs[0], {QStringLiteral("T_bed")});
    ASSERT_TRUE(env.air && env.material);
    EXPECT_DOUBLE_EQ(env.air->mean_C, 20.5);
    const double end_s = 30.0 * 59;
    EXPECT_NEAR(env.material->start_C, 22, 1e-12);
    EXPECT_NEAR(env.material->end_C, materialAt(end_s), 1e-12);
    EXPECT_NEAR(env.material->min_C, 22, 1e-12);
    EXPECT_NEAR(env.material->max_C, materialAt(end_s), 1e-12);
    // Samples every 60 s from 0 to 1740 s inside the test: their mean is θ(870 s).
    EXPECT_NEAR(env.material->mean_C, materialAt(870), 1e-12);
}

// --- the acceptance of a run --------------------------------------------------

TEST(PositioningAcceptance, givesPassFailAndNotProvenFromOneSpecification) {
    const Campaign c = warmCampaign();
    AcceptanceSpecification spec;
    spec.uncertainty.device_um = 0.4;
    spec.uncertainty.eve_um = 1.0;
    const PositioningAcceptance first = evaluateAcceptance(c, c.runs[0], spec);
    ASSERT_TRUE(first.ok()) << first.error.toStdString();
    const double E = first.evaluation.axis.e_um, R = first.evaluation.axis.r_um;
    const double UE = first.budget.find(QStringLiteral("E"))->expanded_um;
    const double UR = first.budget.find(QStringLiteral("R"))->expanded_um;
    // U(R) = 2·√(0.2² + (1/(2√3))²)
    EXPECT_NEAR(UR, 2 * std::hypot(0.2, 1 / (2 * kSqrt3)), 1e-12);
    spec.axes[QStringLiteral("X")].iso230_2_um = {
        {QStringLiteral("E"), E + UE + 0.1},                               // conformance proven
        {QStringLiteral("R"), R - UR - 0.1},                               // non-conformance proven
        {QStringLiteral("B"), 1e-3 + first.evaluation.axis.reversal_um}};  // within U of T
    const PositioningAcceptance result = evaluateAcceptance(c, c.runs[0], spec);
    ASSERT_EQ(result.decisions.size(), 3u);
    // In parameter order: E, R, B.
    EXPECT_EQ(result.decisions[0].parameter, QStringLiteral("E"));
    EXPECT_EQ(result.decisions[0].verdict, Verdict::Pass);
    EXPECT_NEAR(result.decisions[0].margin_um, 0.1, 1e-9);
    EXPECT_EQ(result.decisions[1].verdict, Verdict::Fail);
    EXPECT_EQ(result.decisions[2].verdict, Verdict::NotProven);
    EXPECT_EQ(result.overall(), Verdict::Fail);
    // The readings were normalised: E is the machine's error at 20 °C, far
    // below the 5.8 µm of expansion the raw readings carry.
    EXPECT_EQ(result.normalisation.mode, Normalisation::Mode::Normalised);
    const Evaluation raw = evaluate(readingsOf(c.runs[0]));
    EXPECT_GT(raw.axis.e_um, E + 4);
}

TEST(PositioningAcceptance, takesTheEnvironmentalVariationErrorFromTheEtveRun) {
    Campaign c = warmCampaign();
    c.channels.push_back(
        {QStringLiteral("D_x"), Quantity::Displacement, ChannelRole::DriftX, {}, {}, {}});
    driftlab::Run etve;
    etve.id = QStringLiteral("E1");
    etve.kind = RunKind::Etve;
    etve.samples.columns = {QStringLiteral("D_x")};
    etve.samples.values.resize(1);
    // A drift of 1 µm per hour for 8 h, sampled every minute.
    for (int minute = 0; minute <= 480; ++minute) {
        etve.samples.time_s.push_back(minute * 60.0);
        etve.samples.values[0].push_back(minute / 60.0);
    }
    c.runs.push_back(etve);
    AcceptanceSpecification spec;
    const PositioningAcceptance result = evaluateAcceptance(c, c.runs[0], spec);
    ASSERT_TRUE(result.ok()) << result.error.toStdString();
    // The positioning test lasts 1770 s: the drift's largest range over any
    // 1770 s window is 1740 s of samples · 1 µm/h = 0.48333 µm (windows end on a sample).
    EXPECT_NEAR(result.budget.conditions.eve_um, 1740.0 / 3600, 1e-9);
    EXPECT_TRUE(result.budget.conditions.eve_source.contains(QStringLiteral("E1")));
}

TEST(DriftAcceptance, decidesTheLargestDriftAndRangeWithTheUncertaintyOfOneTarget) {
    ProbeDriftEvaluation e;
    e.probes.resize(2);
    e.probes[0].drift.max_drift_um = -7.5;  // the largest magnitude, with its sign
    e.probes[0].drift.range_um = 8;
    e.probes[1].drift.max_drift_um = 3;
    e.probes[1].drift.range_um = 9.5;
    const DriftFigures figures = driftFigures(e);
    EXPECT_DOUBLE_EQ(figures.max_drift_um, 7.5);
    EXPECT_DOUBLE_EQ(figures.drift_range_um, 9.5);
    AcceptanceSpecification spec;
    spec.uncertainty.device_um = 0.4;  // u = 0.2
    spec.uncertainty.eve_um = 1.5;     // u = 1.5/(2√3) = 0.43301
    // U = 2·√(0.2² + 0.43301²) = 2·0.47697 = 0.95394 µm
    EXPECT_NEAR(driftExpandedUncertainty_um(spec.uncertainty), 0.95394, 1e-5);
    spec.axes[QStringLiteral("Z")].iso230_3_um = {{QStringLiteral("max_drift"), 8},
                                                  {QStringLiteral("drift_range"), 10}};
    EXPECT_TRUE(driftDecisions(spec, QStringLiteral("X"), figures).empty());
    const auto decisions = driftDecisions(spec, QStringLiteral("Z"), figures);
    ASSERT_EQ(decisions.size(), 2u);
    EXPECT_EQ(decisions[0].parameter, QStringLiteral("max_drift"));
    EXPECT_EQ(decisions[0].verdict, Verdict::NotProven);  // 7.5 + 0.95 > 8
    EXPECT_EQ(decisions[1].verdict, Verdict::NotProven);  // 9.5 + 0.95 > 10
    spec.axes[QStringLiteral("Z")].iso230_3_um[QStringLiteral("drift_range")] = 11;
    EXPECT_EQ(driftDecisions(spec, QStringLiteral("Z"), figures)[1].verdict, Verdict::Pass);
}

// --- the specification file ---------------------------------------------------

std::optional<AcceptanceSpecification> parse(const char* json, QString* error) {
    return parseAcceptanceSpecification(QJsonDocument::fromJson(json).object(),
                                        QStringLiteral("spec.json"), error);
}

TEST(AcceptanceSpecification, roundTripsThroughJson) {
    QString error;
    const auto spec = parse(R"({"format": "driftlab.acceptance/1",
        "axes": {"X": {"iso230_2_um": {"A": 12, "R": 4}, "iso230_3_um": {"max_drift": 20}}},
        "uncertainty": {"device_um": 0.2, "device_ppm": 0.5, "eve_run": "E1"},
        "temperature": {"material_channels": ["T_bed"], "expansion_per_K": 1.15e-5}})",
                            &error);
    ASSERT_TRUE(spec) << error.toStdString();
    EXPECT_DOUBLE_EQ(spec->tolerancesOf(QStringLiteral("X"))->iso230_2_um.at(QStringLiteral("A")),
                     12);
    const auto again = parseAcceptanceSpecification(toJson(*spec), QStringLiteral("again"), &error);
    ASSERT_TRUE(again) << error.toStdString();
    EXPECT_EQ(*again, *spec);
}

TEST(AcceptanceSpecification, refusesWhatWouldPassAnAxisSilently) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"axes": {"X": {"iso230_2_um": {"a": 12}}}})", "spec.json.axes.X.iso230_2_um.'a'"},
        {R"({"axes": {"X": {"iso230_2_um": {"A": -1}}}})", "spec.json.axes.X.iso230_2_um.A"},
        {R"({"uncertainty": {"eve": 1}})", "spec.json.uncertainty.'eve'"},
        {R"({"uncertainty": {"eve_um": 1, "eve_run": "E1"}})", "eve_run"},
        {R"({"temperature": {"machine_compensates": true, "normalise": true}})", "twice"},
        {R"({"temperature": {"material_channels": ["a", "b", "c", "d"]}})", "one to three"},
        {R"({"format": "driftlab.campaign/1"})", "spec.json.format"},
    };
    for (const auto& [json, named] : cases) {
        QString error;
        EXPECT_FALSE(parse(json, &error)) << json;
        EXPECT_TRUE(error.contains(QString::fromUtf8(named)))
            << json << " → " << error.toStdString();
    }
}

TEST(AcceptanceSpecification, refusesAKeyNamedTwiceInTheFile) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("spec.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"axes": {"X": {"iso230_2_um": {"A": 12, "A": 40}}}})");
    file.close();
    QString error;
    EXPECT_FALSE(readAcceptanceSpecification(path, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("A"))) << error.toStdString();
}

}  // namespace
}  // namespace driftlab::iso
