#include "core/procedures/Procedure.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>
#include <cmath>
#include <random>

#include "core/procedures/ProcedureJsonReader.h"
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
    r.positive("sample_interval_s", p.sample_interval_s);
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
