// Procedure files: the shipped ones parse and plan; every bad value is
// refused with its key path.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <cmath>
#include <limits>

#include "core/procedures/ProcedurePlan.h"
#include "tests/procedures/ProcedureTestSupport.h"

using namespace driftlab;
using namespace driftlab::procedures;
using namespace driftlab::procedures::test;

TEST(ProcedureFiles, everyShippedProcedureParsesPlansAndRoundTrips) {
    const QStringList files =
        QDir(procedureDir()).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    EXPECT_EQ(files, QStringList({"etve-8h.json", "iso230-2-pilgrim.json", "iso230-2-x-axis.json",
                                  "iso230-3-x-axis.json", "moving-states-s1-s5.json",
                                  "spindle-iso230-3.json"}));
    for (const QString& file : files) {
        SCOPED_TRACE(file.toStdString());
        QString error;
        const auto p = loadProcedureFile(procedureDir() + QLatin1Char('/') + file, &error);
        ASSERT_TRUE(p) << error.toStdString();
        EXPECT_TRUE(error.isEmpty());
        EXPECT_FALSE(p->name.isEmpty());
        const std::vector<PlannedRun> runs = planRuns(*p);
        ASSERT_FALSE(runs.empty());
        for (const PlannedRun& run : runs) {
            EXPECT_GT(run.duration_s, 0) << run.id.toStdString();
            EXPECT_FALSE(run.description.isEmpty());
        }
        // What toJson writes reads back to the same procedure.
        const auto again = parseProcedure(toJson(*p), &error);
        ASSERT_TRUE(again) << error.toStdString();
        EXPECT_EQ(toJson(*again), toJson(*p));
    }
}

TEST(ProcedureFiles, kindNamesRoundTrip) {
    for (auto kind : {ProcedureKind::Iso230_2, ProcedureKind::Iso230_3Axis, ProcedureKind::Etve,
                      ProcedureKind::Spindle, ProcedureKind::MovingStates})
        EXPECT_EQ(procedureKindFromString(toString(kind)), kind);
    EXPECT_EQ(toString(ProcedureKind::Iso230_3Axis), QStringLiteral("iso230-3-axis"));
    EXPECT_FALSE(procedureKindFromString(QStringLiteral("iso230-4")));
}

TEST(ProcedureFiles, missingOptionalKeysTakeTheDefaults) {
    const QJsonObject json{
        {"format", "driftlab.procedure/1"}, {"name", "minimal"}, {"kind", "iso230-2"}};
    QString error;
    const auto p = parseProcedure(json, &error);
    ASSERT_TRUE(p) << error.toStdString();
    ASSERT_TRUE(p->positioning);
    EXPECT_EQ(p->travel_mm, (RangeMm{0, 700}));
    EXPECT_EQ(p->positioning->cycles, 5);
    EXPECT_EQ(p->positioning->span_mm, (RangeMm{5, 695}));
    EXPECT_EQ(p->on_device_loss, DeviceLossPolicy::Continue);
}

TEST(ProcedureFiles, loadErrorsStartWithThePathAndGiveTheSyntaxOffset) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("{\n  \"format\": \"driftlab.procedure/1\",\n  \"name\": }\n");
    f.close();
    QString error;
    EXPECT_FALSE(loadProcedureFile(path, &error));
    EXPECT_TRUE(error.startsWith(path + QStringLiteral(": not valid JSON at offset ")))
        << error.toStdString();

    EXPECT_FALSE(loadProcedureFile(dir.filePath(QStringLiteral("none.json")), &error));
    EXPECT_TRUE(error.startsWith(dir.filePath(QStringLiteral("none.json")) + ": "));

    // A valid file with one bad value: the key path follows the file path.
    const QJsonObject bad = withValue(toJson(shipped("etve-8h.json")), {"etve", "duration_s"}, 0);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(QJsonDocument(bad).toJson());
    f.close();
    EXPECT_FALSE(loadProcedureFile(path, &error));
    EXPECT_EQ(error, path + QStringLiteral(": procedure.etve.duration_s: must be a positive "
                                           "number, got 0"));
}

namespace {

struct BadCase {
    const char* base;  ///< shipped file the edit is made on
    QStringList path;
    QJsonValue value;
    const char* error;  ///< the start of the expected error
};

QJsonObject state(const char* id, double feed, double from, double to) {
    return {{"run_id", id}, {"feed_mm_min", feed}, {"range_mm", QJsonArray{from, to}}};
}

const QJsonValue kRemove = QJsonValue(QJsonValue::Undefined);
const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(ProcedureValidation, everyBadValueIsRefusedNamingItsKey) {
    const char* P = "iso230-2-x-axis.json";
    const char* T = "iso230-3-x-axis.json";
    const char* M = "moving-states-s1-s5.json";
    const char* S = "spindle-iso230-3.json";
    const std::vector<BadCase> cases = {
        {P, {"format"}, kRemove, "procedure.format: is required"},
        {P,
         {"format"},
         "driftlab.procedure/2",
         "procedure.format: must be \"driftlab.procedure/1\""},
        {P, {"name"}, kRemove, "procedure.name: is required"},
        {P, {"name"}, 5, "procedure.name: must be a string, got 5"},
        {P, {"kind"}, "iso230-4", "procedure.kind: must be one of iso230-2,"},
        {P, {"knid"}, "iso230-2", "procedure.knid: unknown key (known keys: format,"},
        {P, {"travel_mm"}, QJsonArray{700, 0}, "procedure.travel_mm: 'to' must be above 'from'"},
        {P, {"sample_interval_s"}, -1, "procedure.sample_interval_s: must be a positive number"},
        {P,
         {"on_device_loss"},
         "abort",
         "procedure.on_device_loss: must be one of continue, pause"},
        {P, {"etve"}, QJsonObject{}, "procedure.etve: belongs to kind \"etve\", not \"iso230-2\""},
        {P,
         {"positioning"},
         QJsonArray{},
         "procedure.positioning: must be an object, got an array"},
        {P,
         {"positioning", "cycles"},
         0,
         "procedure.positioning.cycles: out of range: must be an integer from 1 to 1000, got 0"},
        {P, {"positioning", "cycles"}, 2.5, "procedure.positioning.cycles: must be an integer"},
        {P,
         {"positioning", "cycles"},
         "5",
         "procedure.positioning.cycles: must be a number, got \"5\""},
        {P, {"positioning", "cycels"}, 5, "procedure.positioning.cycels: unknown key"},
        {P,
         {"positioning", "feed_mm_min"},
         0,
         "procedure.positioning.feed_mm_min: must be a positive"},
        {P, {"positioning", "dwell_s"}, -1, "procedure.positioning.dwell_s: must not be negative"},
        {P, {"positioning", "dwell_s"}, kNaN, "procedure.positioning.dwell_s: must be a number"},
        {P,
         {"positioning", "dwell_s"},
         true,
         "procedure.positioning.dwell_s: must be a number, got true"},
        {P,
         {"positioning", "span_mm"},
         QJsonArray{-10, 690},
         "procedure.positioning.span_mm: [-10, 690] mm is outside the travel"},
        {P,
         {"positioning", "span_mm"},
         QJsonArray{5},
         "procedure.positioning.span_mm: must be [from, to]"},
        {P, {"positioning", "targets_per_metre"}, 4, "procedure.positioning.targets_per_metre:"},
        {P,
         {"positioning", "targets_per_metre"},
         1.4e11,
         "procedure.positioning.targets_per_metre: out of range: at most 1000 (a 1 mm pitch), "
         "got 140000000000"},
        {P,
         {"positioning", "irregularity"},
         0.1,
         "procedure.positioning.irregularity: must be below 0.1"},
        {P,
         {"positioning", "irregularity"},
         -0.01,
         "procedure.positioning.irregularity: must not be negative"},
        {P, {"positioning", "seed"}, -1, "procedure.positioning.seed: must be an integer from 0"},
        {P,
         {"positioning", "order"},
         "zigzag",
         "procedure.positioning.order: must be one of linear, pilgrim"},
        {P,
         {"positioning", "overrun_mm"},
         10,
         "procedure.positioning.overrun_mm: 10 mm past the span"},
        {P,
         {"positioning", "overrun_mm"},
         0,
         "procedure.positioning.overrun_mm: must be a positive"},
        {P, {"positioning", "run_id"}, "P 1", "procedure.positioning.run_id: a run id is letters"},
        {T,
         {"thermal_distortion", "range_mm"},
         QJsonArray{210, 800},
         "procedure.thermal_distortion.range_mm: [210, 800] mm is outside"},
        {T,
         {"thermal_distortion", "max_warmup_s"},
         0,
         "procedure.thermal_distortion.max_warmup_s: must be a positive"},
        {T,
         {"thermal_distortion", "cooldown_s"},
         -60,
         "procedure.thermal_distortion.cooldown_s: must not be negative"},
        {T,
         {"thermal_distortion", "targets"},
         1,
         "procedure.thermal_distortion.targets: out of range: must be an integer from 2 to 10000, "
         "got 1"},
        {T,
         {"thermal_distortion", "stabilisation_um"},
         0,
         "procedure.thermal_distortion.stabilisation_um:"},
        {T,
         {"thermal_distortion", "overrun_mm"},
         400,
         "procedure.thermal_distortion.overrun_mm: 400 mm on each side"},
        {"etve-8h.json",
         {"etve", "duration_s"},
         -5,
         "procedure.etve.duration_s: must be a positive"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{},
         "procedure.spindle.blocks: must hold at least one block"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{QJsonObject{{"speed_rpm", 3000}}},
         "procedure.spindle.blocks[0].duration_s: is required"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{QJsonObject{{"duration_s", 60}, {"speed_rpm", -1}}},
         "procedure.spindle.blocks[0].speed_rpm: must not be negative"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{QJsonObject{{"duration_s", 60}, {"rpm", 1}}},
         "procedure.spindle.blocks[0].rpm: unknown key"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{60},
         "procedure.spindle.blocks[0]: must be an object, got 60"},
        {M, {"moving_states"}, kRemove, "procedure.moving_states: is required"},
        {M,
         {"moving_states", "states"},
         QJsonArray{},
         "procedure.moving_states.states: must list at least one"},
        {M,
         {"moving_states", "states"},
         QJsonArray{state("S1", 8000, 210, 490), state("S1", 6500, 210, 490)},
         "procedure.moving_states.states[1].run_id: \"S1\" is used by an earlier state"},
        {M,
         {"moving_states", "states"},
         QJsonArray{state("S-1", 8000, 210, 490)},
         "procedure.moving_states.states[0].run_id: a run id is letters"},
        {M,
         {"moving_states", "states"},
         QJsonArray{state("S1", 0, 210, 490)},
         "procedure.moving_states.states[0].feed_mm_min: must be a positive"},
        {M,
         {"moving_states", "states"},
         QJsonArray{state("S1", 8000, 0, 710)},
         "procedure.moving_states.states[0].range_mm: [0, 710] mm is outside the travel [0, 700] "
         "mm"},
        {M,
         {"moving_states", "states"},
         QJsonArray{QJsonObject{{"feed_mm_min", 8000}}},
         "procedure.moving_states.states[0].run_id: is required"},
        {M, {"moving_states", "block_s"}, 0, "procedure.moving_states.block_s: must be a positive"},
        // What a machine and a store can hold: refused at once, naming the key.
        {P,
         {"sample_interval_s"},
         1e-9,
         "procedure.sample_interval_s: out of range: must be from 0.001 to 3600, got 1e-09"},
        {P,
         {"positioning", "cycles"},
         1099511627776.0,
         "procedure.positioning.cycles: out of range: must be an integer from 1 to 1000, got "
         "1.09951162778e+12"},
        {P,
         {"positioning"},
         QJsonObject{{"cycles", 1000}, {"targets_per_metre", 1000}},
         "procedure.positioning: plans 1380000 interferometer readings in a run, more than the "
         "1000000 it may hold; fewer cycles or targets_per_metre"},
        {P,
         {"positioning", "targets_per_metre"},
         1e9,
         "procedure.positioning.targets_per_metre: out of range: at most 1000 (a 1 mm pitch), "
         "got 1000000000"},
        {P,
         {"positioning", "feed_mm_min"},
         1e7,
         "procedure.positioning.feed_mm_min: out of range: must be at most 200000, got 10000000"},
        {P,
         {"positioning", "feed_mm_min"},
         0.01,
         "procedure.positioning.feed_mm_min: out of range: must be from 1 to 200000, got 0.01"},
        {P,
         {"travel_mm"},
         QJsonArray{0, 1e300},
         "procedure.travel_mm: out of range: the ends must be within ±100000 mm"},
        {"etve-8h.json",
         {"etve", "duration_s"},
         1e7,
         "procedure.etve.duration_s: out of range: must be at most 2592000, got 10000000"},
        {"etve-8h.json",
         {"sample_interval_s"},
         0.001,
         "procedure.sample_interval_s: run E1 would log 28800000 sample rows (28800 s every "
         "0.001 s), more than the 20000000 a run may hold"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{QJsonObject{{"duration_s", 1e300}, {"speed_rpm", 3000}}},
         "procedure.spindle.blocks[0].duration_s: out of range: must be at most 2592000"},
        {S,
         {"spindle", "blocks"},
         QJsonArray{QJsonObject{{"duration_s", 60}, {"speed_rpm", 1e6}}},
         "procedure.spindle.blocks[0].speed_rpm: out of range: must be at most 200000"},
        {T, {"thermal_distortion", "interval_s"}, 1e-6, "procedure.thermal_distortion: plans "},
        {M,
         {"moving_states", "states"},
         QJsonArray{QJsonObject{{"run_id", "S1"},
                                {"feed_mm_min", 200000},
                                {"range_mm", QJsonArray{210, 211}},
                                {"warmup_s", 2592000}}},
         "procedure.moving_states: plans 8640190388 motion segments in a run, more than the "
         "5000000"},
    };
    for (const BadCase& c : cases) {
        const QJsonObject json = withValue(toJson(shipped(c.base)), c.path, c.value);
        QString error;
        EXPECT_FALSE(parseProcedure(json, &error)) << c.error;
        EXPECT_TRUE(error.startsWith(QString::fromUtf8(c.error)))
            << "expected: " << c.error << "\n     got: " << error.toStdString();
    }
}

TEST(ProcedureFiles, aKeyNamedTwiceIsRefusedWithBothLines) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("twice.json"));
    auto load = [&](const QByteArray& text) {
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
        f.close();
        QString error;
        EXPECT_FALSE(loadProcedureFile(path, &error));
        return error;
    };
    EXPECT_EQ(load(R"({"name":"a","name":"b","format":"driftlab.procedure/1","kind":"etve"})"),
              path + QStringLiteral(": procedure.name: named twice in one object (lines 1 and "
                                    "1); only one may stand"));
    EXPECT_EQ(load("{\"format\": \"driftlab.procedure/1\", \"name\": \"p\", \"kind\": \"etve\",\n"
                   " \"etve\": {\"duration_s\": 60,\n"
                   "          \"run_id\": \"E1\",\n"
                   "          \"duration_\\u0073\": 6000}}"),
              path + QStringLiteral(": procedure.etve.duration_s: named twice in one object "
                                    "(lines 2 and 4); only one may stand"));
    // The same key in two objects, and key text inside string values, are fine.
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(R"({"format": "driftlab.procedure/1", "name": "name, \"name\": {", "kind":
        "moving-states", "moving_states": {"states": [{"run_id": "S1", "feed_mm_min": 8000,
        "range_mm": [210, 490]}, {"run_id": "S2", "feed_mm_min": 6000, "range_mm": [210, 490]}]}})");
    f.close();
    QString error;
    EXPECT_TRUE(loadProcedureFile(path, &error)) << error.toStdString();
}
