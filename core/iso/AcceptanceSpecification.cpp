#include "core/iso/AcceptanceSpecification.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "core/domain/JsonDuplicateKeys.h"
#include "core/domain/MessageText.h"

namespace driftlab::iso {

const QStringList& iso230_2ParameterKeys() {
    static const QStringList keys{
        QStringLiteral("A"), QStringLiteral("A_up"), QStringLiteral("A_down"),
        QStringLiteral("E"), QStringLiteral("E_up"), QStringLiteral("E_down"),
        QStringLiteral("R"), QStringLiteral("R_up"), QStringLiteral("R_down"),
        QStringLiteral("B"), QStringLiteral("M")};
    return keys;
}

const QStringList& iso230_3ParameterKeys() {
    static const QStringList keys{QStringLiteral("max_drift"), QStringLiteral("drift_range")};
    return keys;
}

const AxisTolerances* AcceptanceSpecification::tolerancesOf(const QString& axis) const {
    const auto it = axes.find(axis);
    return it == axes.end() ? nullptr : &it->second;
}

namespace {

/// A specification error; its text names the key path.
struct SpecificationError : std::runtime_error {
    explicit SpecificationError(const QString& text) : std::runtime_error(text.toStdString()) {}
};

/// Walks one JSON object, taking its keys one by one, and refuses what is left.
class ObjectReader {
public:
    ObjectReader(const QJsonObject& object, QString path)
        : m_object(object), m_path(std::move(path)) {}

    QString pathOf(const QString& key) const { return m_path + QLatin1Char('.') + key; }

    bool has(const QString& key) const { return m_object.contains(key); }

    double nonNegative(const QString& key, double fallback) {
        if (!take(key)) return fallback;
        const QJsonValue value = m_object.value(key);
        if (!value.isDouble() || !std::isfinite(value.toDouble()) || value.toDouble() < 0)
            fail(key, QStringLiteral("must be a number of 0 or more"));
        return value.toDouble();
    }

    double positive(const QString& key, double fallback) {
        const double value = nonNegative(key, fallback);
        if (has(key) && value <= 0) fail(key, QStringLiteral("must be a number above 0"));
        return value;
    }

    std::optional<double> optionalNumber(const QString& key) {
        if (!has(key)) return std::nullopt;
        if (!take(key) || !m_object.value(key).isDouble() ||
            !std::isfinite(m_object.value(key).toDouble()))
            fail(key, QStringLiteral("must be a number"));
        return m_object.value(key).toDouble();
    }

    bool boolean(const QString& key, bool fallback) {
        if (!take(key)) return fallback;
        if (!m_object.value(key).isBool()) fail(key, QStringLiteral("must be true or false"));
        return m_object.value(key).toBool();
    }

    QString text(const QString& key) {
        if (!take(key)) return {};
        if (!m_object.value(key).isString()) fail(key, QStringLiteral("must be a string"));
        return m_object.value(key).toString();
    }

    QStringList texts(const QString& key) {
        if (!take(key)) return {};
        if (!m_object.value(key).isArray())
            fail(key, QStringLiteral("must be an array of channel ids"));
        QStringList result;
        for (const QJsonValue& v : m_object.value(key).toArray()) {
            if (!v.isString()) fail(key, QStringLiteral("must be an array of channel ids"));
            result << v.toString();
        }
        return result;
    }

    QJsonObject object(const QString& key) {
        if (!take(key)) return {};
        if (!m_object.value(key).isObject()) fail(key, QStringLiteral("must be an object"));
        return m_object.value(key).toObject();
    }

    /// Every key not taken is a mistake: a typo must not pass as "not set".
    void refuseTheRest(const QStringList& allowed) const {
        for (auto it = m_object.begin(); it != m_object.end(); ++it)
            if (!m_taken.contains(it.key()))
                throw SpecificationError(
                    QStringLiteral("%1: unknown key (known here: %2)")
                        .arg(pathOf(quotedText(it.key())), allowed.join(QStringLiteral(", "))));
    }

    [[noreturn]] void fail(const QString& key, const QString& why) const {
        throw SpecificationError(pathOf(key) + QStringLiteral(": ") + why);
    }

private:
    bool take(const QString& key) {
        m_taken << key;
        return m_object.contains(key);
    }

    const QJsonObject& m_object;
    QString m_path;
    QStringList m_taken;
};

std::map<QString, double> readTolerances(const QJsonObject& object, const QString& path,
                                         const QStringList& keys) {
    ObjectReader reader(object, path);
    std::map<QString, double> tolerances;
    for (const QString& key : keys)
        if (reader.has(key)) tolerances[key] = reader.positive(key, 0);
    reader.refuseTheRest(keys);
    return tolerances;
}

AxisTolerances readAxis(const QJsonObject& object, const QString& path) {
    ObjectReader reader(object, path);
    AxisTolerances axis;
    axis.iso230_2_um =
        readTolerances(reader.object(QStringLiteral("iso230_2_um")),
                       reader.pathOf(QStringLiteral("iso230_2_um")), iso230_2ParameterKeys());
    axis.iso230_3_um =
        readTolerances(reader.object(QStringLiteral("iso230_3_um")),
                       reader.pathOf(QStringLiteral("iso230_3_um")), iso230_3ParameterKeys());
    reader.refuseTheRest({QStringLiteral("iso230_2_um"), QStringLiteral("iso230_3_um")});
    return axis;
}

SetupUncertainty readUncertainty(const QJsonObject& object, const QString& path) {
    ObjectReader r(object, path);
    SetupUncertainty u;
    u.device_um = r.nonNegative(QStringLiteral("device_um"), u.device_um);
    u.device_ppm = r.nonNegative(QStringLiteral("device_ppm"), u.device_ppm);
    u.device_k = r.positive(QStringLiteral("device_k"), u.device_k);
    u.air_temperature_K = r.nonNegative(QStringLiteral("air_temperature_K"), 0);
    u.air_pressure_hPa = r.nonNegative(QStringLiteral("air_pressure_hPa"), 0);
    u.air_humidity_pct = r.nonNegative(QStringLiteral("air_humidity_pct"), 0);
    u.material_temperature_K = r.nonNegative(QStringLiteral("material_temperature_K"), 0);
    u.expansion_per_K = r.nonNegative(QStringLiteral("expansion_per_K"), 0);
    u.misalignment_mm = r.nonNegative(QStringLiteral("misalignment_mm"), 0);
    if (r.has(QStringLiteral("eve_um"))) u.eve_um = r.nonNegative(QStringLiteral("eve_um"), 0);
    u.eve_run = r.text(QStringLiteral("eve_run"));
    if (u.eve_um && !u.eve_run.isEmpty())
        r.fail(QStringLiteral("eve_run"),
               QStringLiteral("give eve_um or eve_run, not both: which would count?"));
    u.coverage_k = r.positive(QStringLiteral("coverage_k"), u.coverage_k);
    r.refuseTheRest({QStringLiteral("device_um"), QStringLiteral("device_ppm"),
                     QStringLiteral("device_k"), QStringLiteral("air_temperature_K"),
                     QStringLiteral("air_pressure_hPa"), QStringLiteral("air_humidity_pct"),
                     QStringLiteral("material_temperature_K"), QStringLiteral("expansion_per_K"),
                     QStringLiteral("misalignment_mm"), QStringLiteral("eve_um"),
                     QStringLiteral("eve_run"), QStringLiteral("coverage_k")});
    return u;
}

TemperatureSetting readTemperature(const QJsonObject& object, const QString& path) {
    ObjectReader r(object, path);
    TemperatureSetting t;
    t.machine_compensates = r.boolean(QStringLiteral("machine_compensates"), false);
    t.normalise = r.boolean(QStringLiteral("normalise"), !t.machine_compensates);
    if (t.machine_compensates && t.normalise)
        r.fail(QStringLiteral("normalise"),
               QStringLiteral("the machine already compensates its temperature; normalising "
                              "again would correct the expansion twice"));
    if (r.has(QStringLiteral("expansion_per_K")))
        t.expansion_per_K = r.nonNegative(QStringLiteral("expansion_per_K"), 0);
    t.material_channels = r.texts(QStringLiteral("material_channels"));
    if (t.material_channels.size() > 3)
        r.fail(QStringLiteral("material_channels"),
               QStringLiteral("%1 channels; ISO 230-2 averages one to three material "
                              "thermometers")
                   .arg(t.material_channels.size()));
    t.material_temperature_C = r.optionalNumber(QStringLiteral("material_temperature_C"));
    r.refuseTheRest({QStringLiteral("machine_compensates"), QStringLiteral("normalise"),
                     QStringLiteral("expansion_per_K"), QStringLiteral("material_channels"),
                     QStringLiteral("material_temperature_C")});
    return t;
}

QJsonObject tolerancesJson(const std::map<QString, double>& tolerances) {
    QJsonObject json;
    for (const auto& [key, value] : tolerances) json[key] = value;
    return json;
}

}  // namespace

std::optional<AcceptanceSpecification> parseAcceptanceSpecification(const QJsonObject& object,
                                                                    const QString& where,
                                                                    QString* error) {
    try {
        ObjectReader r(object, where);
        const QString format = r.text(QStringLiteral("format"));
        if (r.has(QStringLiteral("format")) && format != kAcceptanceFormat)
            r.fail(QStringLiteral("format"),
                   QStringLiteral("%1 is not %2").arg(quotedText(format), kAcceptanceFormat));
        AcceptanceSpecification spec;
        const QJsonObject axes = r.object(QStringLiteral("axes"));
        for (auto it = axes.begin(); it != axes.end(); ++it) {
            const QString path = r.pathOf(QStringLiteral("axes.") + it.key());
            if (!it.value().isObject())
                throw SpecificationError(path + QStringLiteral(": must be an object"));
            spec.axes[it.key()] = readAxis(it.value().toObject(), path);
        }
        spec.uncertainty = readUncertainty(r.object(QStringLiteral("uncertainty")),
                                           r.pathOf(QStringLiteral("uncertainty")));
        spec.temperature = readTemperature(r.object(QStringLiteral("temperature")),
                                           r.pathOf(QStringLiteral("temperature")));
        r.refuseTheRest({QStringLiteral("format"), QStringLiteral("axes"),
                         QStringLiteral("uncertainty"), QStringLiteral("temperature")});
        return spec;
    } catch (const SpecificationError& e) {
        if (error) *error = QString::fromStdString(e.what());
        return std::nullopt;
    }
}

std::optional<AcceptanceSpecification> readAcceptanceSpecification(const QString& path,
                                                                   QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("%1: cannot open: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    const QByteArray bytes = file.readAll();
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject()) {
        if (error)
            *error = QStringLiteral("%1: not a JSON object (%2 at byte %3)")
                         .arg(path, parseError.errorString())
                         .arg(parseError.offset);
        return std::nullopt;
    }
    if (const auto duplicate = findDuplicateJsonKey(bytes, path)) {
        if (error) *error = duplicate->toString();
        return std::nullopt;
    }
    return parseAcceptanceSpecification(document.object(), path, error);
}

std::optional<AcceptanceSpecification> campaignAcceptance(const Campaign& campaign,
                                                          QString* error) {
    const QJsonValue own = campaign.extra.value(QStringLiteral("acceptance"));
    if (own.isUndefined()) return std::nullopt;
    if (!own.isObject()) {
        if (error) *error = QStringLiteral("campaign.json acceptance: must be an object");
        return std::nullopt;
    }
    return parseAcceptanceSpecification(own.toObject(), QStringLiteral("campaign.json acceptance"),
                                        error);
}

QJsonObject toJson(const AcceptanceSpecification& s) {
    QJsonObject axes;
    for (const auto& [name, axis] : s.axes)
        axes[name] = QJsonObject{{QStringLiteral("iso230_2_um"), tolerancesJson(axis.iso230_2_um)},
                                 {QStringLiteral("iso230_3_um"), tolerancesJson(axis.iso230_3_um)}};
    const SetupUncertainty& u = s.uncertainty;
    QJsonObject uncertainty{{QStringLiteral("device_um"), u.device_um},
                            {QStringLiteral("device_ppm"), u.device_ppm},
                            {QStringLiteral("device_k"), u.device_k},
                            {QStringLiteral("air_temperature_K"), u.air_temperature_K},
                            {QStringLiteral("air_pressure_hPa"), u.air_pressure_hPa},
                            {QStringLiteral("air_humidity_pct"), u.air_humidity_pct},
                            {QStringLiteral("material_temperature_K"), u.material_temperature_K},
                            {QStringLiteral("expansion_per_K"), u.expansion_per_K},
                            {QStringLiteral("misalignment_mm"), u.misalignment_mm},
                            {QStringLiteral("coverage_k"), u.coverage_k}};
    if (u.eve_um) uncertainty[QStringLiteral("eve_um")] = *u.eve_um;
    if (!u.eve_run.isEmpty()) uncertainty[QStringLiteral("eve_run")] = u.eve_run;
    const TemperatureSetting& t = s.temperature;
    QJsonObject temperature{{QStringLiteral("machine_compensates"), t.machine_compensates},
                            {QStringLiteral("normalise"), t.normalise}};
    if (t.expansion_per_K) temperature[QStringLiteral("expansion_per_K")] = *t.expansion_per_K;
    if (!t.material_channels.isEmpty())
        temperature[QStringLiteral("material_channels")] =
            QJsonArray::fromStringList(t.material_channels);
    if (t.material_temperature_C)
        temperature[QStringLiteral("material_temperature_C")] = *t.material_temperature_C;
    return {{QStringLiteral("format"), kAcceptanceFormat},
            {QStringLiteral("axes"), axes},
            {QStringLiteral("uncertainty"), uncertainty},
            {QStringLiteral("temperature"), temperature}};
}

}  // namespace driftlab::iso
