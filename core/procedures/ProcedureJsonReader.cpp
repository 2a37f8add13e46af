#include "core/procedures/ProcedureJsonReader.h"

#include <QRegularExpression>
#include <cmath>

#include "core/domain/MessageText.h"

namespace driftlab::procedures {
namespace {

/// A range as the procedure file writes it (an array), for its errors.
QString jsonRangeText(const RangeMm& r) {
    return QStringLiteral("[%1, %2] mm").arg(numberText(r.from_mm), numberText(r.to_mm));
}

}  // namespace

QString describeJsonValue(const QJsonValue& value) {
    switch (value.type()) {
        case QJsonValue::Null:
            return QStringLiteral("null");
        case QJsonValue::Bool:
            return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
        case QJsonValue::Double:
            return numberText(value.toDouble());
        case QJsonValue::String:
            return QStringLiteral("\"%1\" (a string)").arg(value.toString());
        case QJsonValue::Array:
            return QStringLiteral("an array");
        case QJsonValue::Object:
            return QStringLiteral("an object");
        case QJsonValue::Undefined:
            break;
    }
    return QStringLiteral("nothing");
}

ObjectReader::ObjectReader(const QJsonObject& object, QString path, const QStringList& known)
    : m_object(object), m_path(std::move(path)) {
    for (auto it = object.begin(); it != object.end(); ++it)
        if (!known.contains(it.key()))
            fail(it.key(), QStringLiteral("unknown key (known keys: %1)").arg(known.join(", ")));
}

void ObjectReader::fail(const QString& key, const QString& why) const {
    throw ProcedureError{pathOf(key) + QStringLiteral(": ") + why};
}

QJsonValue ObjectReader::numberValue(const QString& key) const {
    const QJsonValue v = m_object.value(key);
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        fail(key, QStringLiteral("must be a number, got %1").arg(describeJsonValue(v)));
    return v;
}

void ObjectReader::number(const QString& key, double& value) {
    if (has(key)) value = numberValue(key).toDouble();
    if (!std::isfinite(value))
        fail(key, QStringLiteral("must be a finite number, got %1").arg(numberText(value)));
}

void ObjectReader::positive(const QString& key, double& value, double at_most) {
    number(key, value);
    if (!(value > 0))
        fail(key, QStringLiteral("must be a positive number, got %1").arg(numberText(value)));
    if (value > at_most) failAbove(key, value, at_most);
}

void ObjectReader::nonNegative(const QString& key, double& value, double at_most) {
    number(key, value);
    if (value < 0) fail(key, QStringLiteral("must not be negative, got %1").arg(numberText(value)));
    if (value > at_most) failAbove(key, value, at_most);
}

void ObjectReader::positiveIn(const QString& key, double& value, double lowest, double highest) {
    positive(key, value, highest);
    if (value < lowest)
        fail(key, QStringLiteral("out of range: must be from %1 to %2, got %3")
                      .arg(numberText(lowest), numberText(highest), numberText(value)));
}

void ObjectReader::failAbove(const QString& key, double value, double at_most) const {
    fail(key, QStringLiteral("out of range: must be at most %1, got %2")
                  .arg(numberText(at_most), numberText(value)));
}

void ObjectReader::integerIn(const QString& key, int& value, int lowest, int highest) {
    double d = value;
    if (has(key)) {
        d = numberValue(key).toDouble();
        if (d != std::floor(d))
            fail(key, QStringLiteral("must be an integer, got %1").arg(numberText(d)));
    }
    if (d < lowest || d > highest)
        fail(key, QStringLiteral("out of range: must be an integer from %1 to %2, got %3")
                      .arg(lowest)
                      .arg(highest)
                      .arg(numberText(d)));
    value = int(d);
}

void ObjectReader::seed(const QString& key, unsigned& value) {
    if (!has(key)) return;
    const double d = numberValue(key).toDouble();
    if (d != std::floor(d) || d < 0 || d > 4294967295.0)
        fail(key,
             QStringLiteral("must be an integer from 0 to 4294967295, got %1").arg(numberText(d)));
    value = unsigned(d);
}

void ObjectReader::string(const QString& key, QString& value, bool required) {
    if (!has(key)) {
        if (required) fail(key, QStringLiteral("is required"));
        return;
    }
    const QJsonValue v = m_object.value(key);
    if (!v.isString())
        fail(key, QStringLiteral("must be a string, got %1").arg(describeJsonValue(v)));
    value = v.toString();
    if (required && value.trimmed().isEmpty()) fail(key, QStringLiteral("must not be empty"));
}

void ObjectReader::runId(const QString& key, QString& value) {
    string(key, value);
    static const QRegularExpression valid(QStringLiteral("^[A-Za-z0-9_]+$"));
    if (!valid.match(value).hasMatch())
        fail(key,
             QStringLiteral("a run id is letters, digits and '_' only, got \"%1\"").arg(value));
}

void ObjectReader::range(const QString& key, RangeMm& value, const RangeMm* within) {
    if (has(key)) {
        const QJsonValue v = m_object.value(key);
        const QJsonArray a = v.toArray();
        if (!v.isArray() || a.size() != 2 || !a[0].isDouble() || !a[1].isDouble() ||
            !std::isfinite(a[0].toDouble()) || !std::isfinite(a[1].toDouble()))
            fail(key, QStringLiteral("must be [from, to] in mm, got %1")
                          .arg(v.isArray() ? QStringLiteral("an array of %1 values").arg(a.size())
                                           : describeJsonValue(v)));
        value = {a[0].toDouble(), a[1].toDouble()};
    }
    if (!(value.to_mm > value.from_mm))
        fail(key, QStringLiteral("'to' must be above 'from', got %1").arg(jsonRangeText(value)));
    if (within && (value.from_mm < within->from_mm || value.to_mm > within->to_mm))
        fail(key, QStringLiteral("%1 is outside the travel %2 (procedure.travel_mm)")
                      .arg(jsonRangeText(value), jsonRangeText(*within)));
}

void ObjectReader::choice(const QString& key, int& index, const QStringList& choices,
                          bool required) {
    if (!has(key)) {
        if (required) fail(key, QStringLiteral("is required (one of %1)").arg(choices.join(", ")));
        return;
    }
    const QJsonValue v = m_object.value(key);
    index = v.isString() ? int(choices.indexOf(v.toString())) : -1;
    if (index < 0)
        fail(key, QStringLiteral("must be one of %1, got %2")
                      .arg(choices.join(", "), describeJsonValue(v)));
}

QJsonObject ObjectReader::object(const QString& key) const {
    if (!has(key)) return {};
    const QJsonValue v = m_object.value(key);
    if (!v.isObject())
        fail(key, QStringLiteral("must be an object, got %1").arg(describeJsonValue(v)));
    return v.toObject();
}

QJsonArray ObjectReader::array(const QString& key) const {
    if (!has(key)) return {};
    const QJsonValue v = m_object.value(key);
    if (!v.isArray())
        fail(key, QStringLiteral("must be an array, got %1").arg(describeJsonValue(v)));
    return v.toArray();
}

}  // namespace driftlab::procedures
