#pragma once
// A test procedure as data (docs/procedures.md): what the engine drives and
// logs. Read from the JSON files in resources/procedures/ by
// parseProcedure(); planned into runs (motion and interferometer readings) by
// ProcedurePlan. ISO 230-3's own numbers are not public here: every value is a
// parameter, and the defaults below are DriftLab's choice (docs/procedures.md).

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/domain/Run.h"

namespace driftlab::procedures {

enum class ProcedureKind {
    Iso230_2,      ///< "iso230-2": bidirectional positioning run
    Iso230_3Axis,  ///< "iso230-3-axis": thermal distortion caused by moving a linear axis
    Etve,          ///< "etve": environmental temperature variation, machine at rest
    Spindle,       ///< "spindle": ISO 230-3 spindle speed programme, five drift probes
    MovingStates,  ///< "moving-states": user sequence of moving states (warm-up, cool-down)
};
QString toString(ProcedureKind kind);
std::optional<ProcedureKind> procedureKindFromString(const QString& text);

enum class ApproachOrder { Linear, Pilgrim };

/// ISO 230-2: targets over `span_mm`, ≥ 5 per metre and at least 5, each
/// shifted from the even grid by a seeded random fraction < 10 % of the
/// interval (so a periodic pitch error is not sampled at one phase).
struct PositioningSpec {
    QString run_id = QStringLiteral("P1");
    RangeMm span_mm{5, 695};        ///< first and last target
    double targets_per_metre = 10;  ///< ≥ 5
    double irregularity = 0.08;     ///< |shift| ≤ this × interval; < 0.1
    unsigned seed = 1;              ///< of the shifts, so a procedure is repeatable
    int cycles = 5;
    ApproachOrder order = ApproachOrder::Linear;
    double feed_mm_min = 3000;
    double overrun_mm = 5;  ///< past the end targets before reversing
    double dwell_s = 3;     ///< standstill before the reading (taken at its end)
};

/// ISO 230-3 thermal distortion caused by moving a linear axis: reciprocate
/// over a range at a feed for `interval_s`, stop, measure the targets; repeat
/// until the change between two successive measurements stays within
/// `stabilisation_um` at every target, or `max_warmup_s` runs out; then cool
/// down, measuring every `cooldown_interval_s` for `cooldown_s`.
struct ThermalDistortionSpec {
    QString run_id = QStringLiteral("T1");
    double feed_mm_min = 8000;
    RangeMm range_mm{210, 490};
    int targets = 11;  ///< equally spaced over the travel, inside it by the overrun
    double interval_s = 600;
    double stabilisation_um = 1.0;
    double max_warmup_s = 14400;
    double cooldown_s = 3600;
    double cooldown_interval_s = 600;
    double pass_feed_mm_min = 3000;
    double dwell_s = 3;
    double overrun_mm = 5;
};

/// ETVE: machine at rest for hours while the room varies; the five drift
/// probes and the temperatures are logged at the sample interval throughout.
struct EtveSpec {
    QString run_id = QStringLiteral("E1");
    double duration_s = 8 * 3600;
};

struct SpindleBlock {
    double duration_s = 0;
    double speed_rpm = 0;  ///< 0 = stop
};
struct SpindleSpec {
    QString run_id = QStringLiteral("SP1");
    std::vector<SpindleBlock> blocks{{1800, 3000}, {1800, 6000}, {900, 0}, {1800, 9000}, {3600, 0}};
};

/// One moving state of a user sequence.
struct MovingStateStep {
    QString run_id;
    double feed_mm_min = 8000;
    RangeMm range_mm{210, 490};
    double warmup_s = 7200;
    double cooldown_s = 3600;
};
struct MovingStatesSpec {
    std::vector<MovingStateStep> states;
    int targets = 11;
    double block_s = 600;
    double cooldown_interval_s = 600;
};

/// What the engine does when a device stops answering.
enum class DeviceLossPolicy { Continue, Pause };

struct Procedure {
    QString name;
    QString description;
    ProcedureKind kind = ProcedureKind::MovingStates;
    RangeMm travel_mm{0, 700};  ///< the axis travel the procedure may use
    double sample_interval_s = 10;
    DeviceLossPolicy on_device_loss = DeviceLossPolicy::Continue;
    /// The one spec of `kind` is set.
    std::optional<PositioningSpec> positioning;
    std::optional<ThermalDistortionSpec> thermal_distortion;
    std::optional<EtveSpec> etve;
    std::optional<SpindleSpec> spindle;
    std::optional<MovingStatesSpec> moving_states;
};

/// Parses and validates a procedure; nullopt with `error` naming the key
/// ("procedure.positioning.cycles: must be at least 1, got 0").
std::optional<Procedure> parseProcedure(const QJsonObject& json, QString* error);
/// Parses the bytes of a procedure file (JSON); nullopt with `error` saying why.
std::optional<Procedure> parseProcedureJson(const QByteArray& bytes, QString* error);
/// Reads a procedure file; errors start with the path.
std::optional<Procedure> loadProcedureFile(const QString& path, QString* error);
QJsonObject toJson(const Procedure& procedure);

/// ISO 230-2 targets as described at PositioningSpec, ascending.
std::vector<double> positioningTargets(const PositioningSpec& spec);

}  // namespace driftlab::procedures
