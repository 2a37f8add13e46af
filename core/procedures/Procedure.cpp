#include "core/procedures/Procedure.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/domain/JsonDuplicateKeys.h"
#include "core/domain/MessageText.h"
#include "core/procedures/ProcedureJsonReader.h"
#include "core/procedures/ProcedureLimits.h"
#include "core/procedures/ProcedurePlan.h"
#include "core/procedures/ProcedureSpecsJson.h"

namespace driftlab::procedures {
namespace {

const QString kFormat = QStringLiteral("driftlab.procedure/1");
const QStringList kKindNames{QStringLiteral("iso230-2"), QStringLiteral("iso230-3-axis"),
                             QStringLiteral("etve"), QStringLiteral("spindle"),
                             QStringLiteral("moving-states")};
/// The key of each kind's own object, in ProcedureKind order.
const QStringList kSpecKeys{QStringLiteral("positioning"), QStringLiteral("thermal_distortion"),
                            QStringLiteral("etve"), QStringLiteral("spindle"),
                            QStringLiteral("moving_states")};
const QStringList kDeviceLoss{QStringLiteral("continue"), QStringLiteral("pause")};

/// Readings and motion segments planning `spec` allocates (warm-up and
/// cool-down passes over the targets, strokes in between).
double movingStateSize(double warmup_s, double block_s, double cooldown_s,
                       double cooldown_interval_s, int targets, const RangeMm& range_mm,
                       double feed_mm_min, double* measurements) {
    const double passes =
        std::ceil(warmup_s / block_s) + std::ceil(cooldown_s / cooldown_interval_s) + 1;
    *measurements = passes * targets * 2;
    const double stroke_s = (range_mm.to_mm - range_mm.from_mm) / feed_mm_min * 60.0;
    return warmup_s / stroke_s + *measurements * 2;
}

/// Refuses a procedure whose plan would not fit a run, counted before
/// planning allocates it: readings, motion, duration and sample rows.
void checkPlannedSize(const Procedure& p, const ObjectReader& r, const QString& key) {
    auto refuse = [&](const QString& what, double count, double limit, const QString& fewer) {
        if (count > limit)
            r.fail(key, QStringLiteral("plans %1 %2 in a run, more than the %3 it may hold; %4")
                            .arg(numberText(count), what, numberText(limit), fewer));
    };
    const QString readings = QStringLiteral("interferometer readings");
    const QString segments = QStringLiteral("motion segments");
    double measurements = 0;
    if (p.positioning) {
        const PositioningSpec& s = *p.positioning;
        const double span_mm = s.span_mm.to_mm - s.span_mm.from_mm;
        const double targets = std::max(5.0, std::ceil(s.targets_per_metre * span_mm / 1000.0));
        refuse(readings, targets * 2 * s.cycles, limits::kMaxMeasurementsPerRun,
               QStringLiteral("fewer cycles or targets_per_metre"));
    }
    if (const auto* s = p.thermal_distortion ? &*p.thermal_distortion : nullptr) {
        const double motion =
            movingStateSize(s->max_warmup_s, s->interval_s, s->cooldown_s, s->cooldown_interval_s,
                            s->targets, s->range_mm, s->feed_mm_min, &measurements);
        refuse(readings, measurements, limits::kMaxMeasurementsPerRun,
               QStringLiteral("longer interval_s or cooldown_interval_s, or fewer targets"));
        refuse(segments, motion, limits::kMaxMotionSegmentsPerRun,
               QStringLiteral("a longer range_mm or a lower feed_mm_min"));
    }
    if (p.moving_states)
        for (const MovingStateStep& step : p.moving_states->states) {
            const MovingStatesSpec& s = *p.moving_states;
            const double motion =
                movingStateSize(step.warmup_s, s.block_s, step.cooldown_s, s.cooldown_interval_s,
                                s.targets, step.range_mm, step.feed_mm_min, &measurements);
            refuse(readings, measurements, limits::kMaxMeasurementsPerRun,
                   QStringLiteral("a longer block_s or cooldown_interval_s, or fewer targets"));
            refuse(segments, motion, limits::kMaxMotionSegmentsPerRun,
                   QStringLiteral("a longer range_mm or a lower feed_mm_min in ") + step.run_id);
        }
    std::vector<PlannedRun> planned;
    try {
        planned = planRuns(p);
    } catch (const std::invalid_argument& e) {
        r.fail(key, QString::fromStdString(e.what()));
    }
    for (const PlannedRun& run : planned) {
        if (run.duration_s > limits::kMaxRunDuration_s)
            r.fail(key, QStringLiteral("run %1 would last %2 s, longer than the %3 s (30 days) a "
                                       "run may last")
                            .arg(run.id, numberText(run.duration_s),
                                 numberText(limits::kMaxRunDuration_s)));
        const double rows = run.duration_s / p.sample_interval_s;
        if (rows > limits::kMaxRowsPerRun)
            r.fail(QStringLiteral("sample_interval_s"),
                   QStringLiteral("run %1 would log %2 sample rows (%3 s every %4 s), more than "
                                  "the %5 a run may hold; a longer interval")
                       .arg(run.id, numberText(std::ceil(rows)), numberText(run.duration_s),
                            numberText(p.sample_interval_s), numberText(limits::kMaxRowsPerRun)));
    }
}

Procedure readProcedure(const QJsonObject& json) {
    QStringList known{"format",        "name",      "description",
                      "kind",          "travel_mm", "sample_interval_s",
                      "on_device_loss"};
    known += kSpecKeys;
    ObjectReader r(json, QStringLiteral("procedure"), known);
    QString format;
    r.string("format", format, true);
    if (format != kFormat)
        r.fail("format", QStringLiteral("must be \"%1\", got \"%2\"").arg(kFormat, format));
    Procedure p;
    r.string("name", p.name, true);
    r.string("description", p.description);
    int kind = 0;
    r.choice("kind", kind, kKindNames, true);
    p.kind = ProcedureKind(kind);
    r.range("travel_mm", p.travel_mm);
    if (std::abs(p.travel_mm.from_mm) > limits::kMaxTravel_mm ||
        std::abs(p.travel_mm.to_mm) > limits::kMaxTravel_mm)
        r.fail("travel_mm", QStringLiteral("out of range: the ends must be within ±%1 mm")
                                .arg(limits::kMaxTravel_mm));
    r.positiveIn("sample_interval_s", p.sample_interval_s, limits::kMinSampleInterval_s,
                 limits::kMaxSampleInterval_s);
    int loss = int(p.on_device_loss);
    r.choice("on_device_loss", loss, kDeviceLoss);
    p.on_device_loss = DeviceLossPolicy(loss);

    for (int k = 0; k < kSpecKeys.size(); ++k)
        if (k != kind && r.has(kSpecKeys[k]))
            r.fail(kSpecKeys[k], QStringLiteral("belongs to kind \"%1\", not \"%2\"")
                                     .arg(kKindNames[k], kKindNames[kind]));
    const QString& key = kSpecKeys[kind];
    const QJsonObject spec = r.object(key);
    const QString path = r.pathOf(key);
    switch (p.kind) {
        case ProcedureKind::Iso230_2:
            p.positioning = readPositioning(spec, path, p.travel_mm);
            break;
        case ProcedureKind::Iso230_3Axis:
            p.thermal_distortion = readThermalDistortion(spec, path, p.travel_mm);
            break;
        case ProcedureKind::Etve:
            p.etve = readEtve(spec, path);
            break;
        case ProcedureKind::Spindle:
            p.spindle = readSpindle(spec, path);
            break;
        case ProcedureKind::MovingStates:
            // Unlike the others this one has no default: the states are the procedure.
            if (!r.has(key)) r.fail(key, QStringLiteral("is required for kind \"moving-states\""));
            p.moving_states = readMovingStates(spec, path, p.travel_mm);
            break;
    }
    checkPlannedSize(p, r, key);
    return p;
}

}  // namespace

QString toString(ProcedureKind kind) {
    return kKindNames[int(kind)];
}

std::optional<ProcedureKind> procedureKindFromString(const QString& text) {
    const auto i = kKindNames.indexOf(text.trimmed());
    if (i < 0) return std::nullopt;
    return ProcedureKind(i);
}

std::optional<Procedure> parseProcedure(const QJsonObject& json, QString* error) {
    try {
        Procedure p = readProcedure(json);
        if (error) error->clear();
        return p;
    } catch (const ProcedureError& e) {
        if (error) *error = e.message;
        return std::nullopt;
    }
}

std::optional<Procedure> parseProcedureJson(const QByteArray& bytes, QString* error) {
    auto failWith = [&](const QString& why) {
        if (error) *error = why;
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return failWith(QStringLiteral("not valid JSON at offset %1: %2")
                            .arg(parseError.offset)
                            .arg(parseError.errorString()));
    if (!doc.isObject()) return failWith(QStringLiteral("a procedure must be a JSON object"));
    if (const auto duplicate = findDuplicateJsonKey(bytes, QStringLiteral("procedure")))
        return failWith(duplicate->toString());
    return parseProcedure(doc.object(), error);
}

std::optional<Procedure> loadProcedureFile(const QString& path, QString* error) {
    QString why;
    std::optional<Procedure> procedure;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        why = file.errorString();
    else
        procedure = parseProcedureJson(file.readAll(), &why);
    if (error) *error = procedure ? QString() : path + QStringLiteral(": ") + why;
    return procedure;
}

QJsonObject toJson(const Procedure& p) {
    QJsonObject json{{"format", kFormat},
                     {"name", p.name},
                     {"description", p.description},
                     {"kind", toString(p.kind)},
                     {"travel_mm", QJsonArray{p.travel_mm.from_mm, p.travel_mm.to_mm}},
                     {"sample_interval_s", p.sample_interval_s},
                     {"on_device_loss", kDeviceLoss[int(p.on_device_loss)]}};
    const QString key = kSpecKeys[int(p.kind)];
    if (p.positioning) json[key] = toJson(*p.positioning);
    if (p.thermal_distortion) json[key] = toJson(*p.thermal_distortion);
    if (p.etve) json[key] = toJson(*p.etve);
    if (p.spindle) json[key] = toJson(*p.spindle);
    if (p.moving_states) json[key] = toJson(*p.moving_states);
    return json;
}

std::vector<double> positioningTargets(const PositioningSpec& spec) {
    const double span_mm = spec.span_mm.to_mm - spec.span_mm.from_mm;
    // Enough targets for the density over the span (ISO 230-2: ≥ 5 per metre),
    // and never fewer than five; the tolerance keeps 10 × 0.7 m from becoming 8.
    const int needed = int(std::ceil(spec.targets_per_metre * span_mm / 1000.0 - 1e-9));
    const int intervals = std::max(4, needed - 1);
    const double interval_mm = span_mm / intervals;
    std::mt19937_64 rng(spec.seed);
    std::vector<double> targets;
    targets.reserve(std::size_t(intervals) + 1);
    for (int i = 0; i <= intervals; ++i) {
        double x = spec.span_mm.from_mm + interval_mm * i;
        if (i == intervals) x = spec.span_mm.to_mm;
        if (i > 0 && i < intervals) {
            // A uniform fraction in [0, 1) from the top 53 bits, written out so
            // that the targets are the same with every standard library.
            const double u = double(rng() >> 11) * 0x1.0p-53;
            x += (2 * u - 1) * spec.irregularity * interval_mm;
        }
        targets.push_back(std::round(x * 1000) / 1000);
    }
    return targets;
}

}  // namespace driftlab::procedures
