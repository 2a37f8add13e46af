#include "acquisition/devices/ChannelRegisterMap.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/domain/JsonDuplicateKeys.h"

namespace driftlab::devices {
namespace {

const QStringList kTopKeys = {"name", "description", "channels"};
const QStringList kChannelKeys = {"id",    "address", "kind", "type",    "word_order",
                                  "scale", "offset",  "unit", "invalid", "comment"};

bool is32Bit(ValueType type) {
    return type == ValueType::Int32 || type == ValueType::UInt32 || type == ValueType::Float32;
}

/// Parses one channel object; `where` names it in errors ("channel 3 (\"t3\")").
class ChannelParser {
public:
    ChannelParser(const QJsonObject& object, QString where, QString* error)
        : m_object(object), m_where(std::move(where)), m_error(error) {}

    bool fail(const QString& key, const QString& what) {
        *m_error = QStringLiteral("%1: key \"%2\": %3").arg(m_where, key, what);
        return false;
    }

    bool string(const QString& key, QString* out) {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined()) return fail(key, QStringLiteral("missing"));
        if (!v.isString() || v.toString().isEmpty())
            return fail(key, QStringLiteral("expected a non-empty string"));
        *out = v.toString();
        return true;
    }

    bool integer(const QString& key, double low, double high, double* out) {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined()) return fail(key, QStringLiteral("missing"));
        double d = 0;
        if (v.isDouble()) {
            d = v.toDouble();
        } else if (v.isString() && v.toString().startsWith(QStringLiteral("0x"))) {
            // Hex strings because module manuals give codes such as 0x7FFF.
            bool ok = false;
            d = double(v.toString().mid(2).toULongLong(&ok, 16));
            if (!ok)
                return fail(key, QStringLiteral("\"%1\" is not a hex number").arg(v.toString()));
        } else {
            return fail(key, QStringLiteral("expected an integer or a \"0x…\" string"));
        }
        if (d != std::floor(d) || d < low || d > high)
            return fail(key,
                        QStringLiteral("%1 is not an integer in %2…%3").arg(d).arg(low).arg(high));
        *out = d;
        return true;
    }

    bool number(const QString& key, double fallback, double* out) {
        const QJsonValue v = m_object.value(key);
        if (v.isUndefined()) {
            *out = fallback;
            return true;
        }
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return fail(key, QStringLiteral("expected a finite number"));
        *out = v.toDouble();
        return true;
    }

    bool parse(ChannelSpec* c) {
        for (auto it = m_object.begin(); it != m_object.end(); ++it)
            if (!kChannelKeys.contains(it.key()))
                return fail(it.key(), QStringLiteral("unknown key (allowed: %1)")
                                          .arg(kChannelKeys.join(QStringLiteral(", "))));
        QString kind, type, word_order;
        double address = 0;
        if (!string(QStringLiteral("id"), &c->id) ||
            !integer(QStringLiteral("address"), 0, 65535, &address) ||
            !string(QStringLiteral("kind"), &kind) || !string(QStringLiteral("type"), &type) ||
            !string(QStringLiteral("unit"), &c->unit) ||
            !number(QStringLiteral("scale"), 1.0, &c->scale) ||
            !number(QStringLiteral("offset"), 0.0, &c->offset))
            return false;
        QString why;
        const auto to_celsius = conversionToDriftLabUnit(Quantity::Temperature, c->unit, &why);
        if (!to_celsius) return fail(QStringLiteral("unit"), why);
        c->to_celsius = *to_celsius;
        c->address = int(address);
        if (kind == QStringLiteral("holding"))
            c->kind = RegisterKind::Holding;
        else if (kind == QStringLiteral("input"))
            c->kind = RegisterKind::Input;
        else
            return fail(QStringLiteral("kind"),
                        QStringLiteral("\"%1\" is not holding or input").arg(kind));
        static const QStringList types = {"int16", "uint16", "int32", "uint32", "float32"};
        const int t = int(types.indexOf(type));
        if (t < 0)
            return fail(QStringLiteral("type"), QStringLiteral("\"%1\" is not one of %2")
                                                    .arg(type, types.join(QStringLiteral(", "))));
        c->type = ValueType(t);
        if (c->scale == 0) return fail(QStringLiteral("scale"), QStringLiteral("must not be 0"));
        if (c->address + c->registerCount() - 1 > 65535)
            return fail(QStringLiteral("address"),
                        QStringLiteral("the value runs past register 65535"));
        if (is32Bit(c->type)) {
            // No default: a wrong guess swaps halves and still yields numbers.
            if (!string(QStringLiteral("word_order"), &word_order)) return false;
            if (word_order == QStringLiteral("high-first"))
                c->word_order = WordOrder::HighFirst;
            else if (word_order == QStringLiteral("low-first"))
                c->word_order = WordOrder::LowFirst;
            else
                return fail(
                    QStringLiteral("word_order"),
                    QStringLiteral("\"%1\" is not high-first or low-first").arg(word_order));
        } else if (m_object.contains(QStringLiteral("word_order"))) {
            return fail(QStringLiteral("word_order"), QStringLiteral("only for 32-bit types"));
        }
        return invalidCodes(c);
    }

    bool invalidCodes(ChannelSpec* c) {
        const QJsonValue v = m_object.value(QStringLiteral("invalid"));
        if (v.isUndefined()) return true;
        if (!v.isArray())
            return fail(QStringLiteral("invalid"), QStringLiteral("expected an array"));
        // Signed or unsigned spellings of the same bit pattern are both accepted.
        const bool wide = is32Bit(c->type);
        const double low = wide ? -2147483648.0 : -32768.0;
        const double high = wide ? 4294967295.0 : 65535.0;
        for (const QJsonValue& code : v.toArray()) {
            ChannelParser one(QJsonObject{{QStringLiteral("invalid"), code}}, m_where, m_error);
            double d = 0;
            if (!one.integer(QStringLiteral("invalid"), low, high, &d)) return false;
            const auto bits = std::uint32_t(std::int64_t(d) & (wide ? 0xFFFFFFFFll : 0xFFFFll));
            c->invalid_raw.push_back(bits);
        }
        return true;
    }

private:
    QJsonObject m_object;
    QString m_where;
    QString* m_error;
};

}  // namespace

int ChannelSpec::registerCount() const {
    return is32Bit(type) ? 2 : 1;
}

std::optional<ChannelRegisterMap> parseChannelRegisterMap(const QByteArray& json, QString* error) {
    QJsonParseError parse_error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parse_error);
    if (parse_error.error != QJsonParseError::NoError) {
        *error = QStringLiteral("not JSON at offset %1: %2")
                     .arg(parse_error.offset)
                     .arg(parse_error.errorString());
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = QStringLiteral("expected a JSON object with \"channels\"");
        return std::nullopt;
    }
    if (const auto duplicate = findDuplicateJsonKey(json, QStringLiteral("map"))) {
        *error = duplicate->toString();
        return std::nullopt;
    }
    const QJsonObject top = doc.object();
    for (auto it = top.begin(); it != top.end(); ++it) {
        if (!kTopKeys.contains(it.key())) {
            *error = QStringLiteral("key \"%1\": unknown key (allowed: %2)")
                         .arg(it.key(), kTopKeys.join(QStringLiteral(", ")));
            return std::nullopt;
        }
    }
    ChannelRegisterMap map;
    map.name = top.value(QStringLiteral("name")).toString();
    map.description = top.value(QStringLiteral("description")).toString();
    const QJsonValue channels = top.value(QStringLiteral("channels"));
    if (!channels.isArray() || channels.toArray().isEmpty()) {
        *error = QStringLiteral("key \"channels\": expected a non-empty array");
        return std::nullopt;
    }
    QSet<QString> ids;
    int index = 0;
    for (const QJsonValue& value : channels.toArray()) {
        ++index;
        const QJsonObject object = value.toObject();
        const QString id = object.value(QStringLiteral("id")).toString();
        const QString where = id.isEmpty()
                                  ? QStringLiteral("channel %1").arg(index)
                                  : QStringLiteral("channel %1 (\"%2\")").arg(index).arg(id);
        if (!value.isObject()) {
            *error = QStringLiteral("%1: expected an object").arg(where);
            return std::nullopt;
        }
        ChannelSpec spec;
        if (!ChannelParser(object, where, error).parse(&spec)) return std::nullopt;
        if (ids.contains(spec.id)) {
            *error = QStringLiteral("%1: key \"id\": \"%2\" is used twice").arg(where, spec.id);
            return std::nullopt;
        }
        ids.insert(spec.id);
        // Two channels on one register would mean a typo in an address.
        for (const ChannelSpec& other : map.channels) {
            if (other.kind == spec.kind && spec.address < other.address + other.registerCount() &&
                other.address < spec.address + spec.registerCount()) {
                *error =
                    QStringLiteral("%1: key \"address\": %2 register %3 overlaps channel \"%4\"")
                        .arg(where, toString(spec.kind))
                        .arg(spec.address)
                        .arg(other.id);
                return std::nullopt;
            }
        }
        map.channels.push_back(spec);
    }
    return map;
}

std::optional<ChannelRegisterMap> loadChannelRegisterMap(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    auto map = parseChannelRegisterMap(file.readAll(), error);
    if (!map) *error = QStringLiteral("%1: %2").arg(path, *error);
    return map;
}

std::uint32_t rawBits(const ChannelSpec& channel, std::span<const std::uint16_t> words) {
    if (channel.registerCount() == 1) return words[0];
    const bool high_first = channel.word_order == WordOrder::HighFirst;
    const std::uint32_t high = high_first ? words[0] : words[1];
    const std::uint32_t low = high_first ? words[1] : words[0];
    return (high << 16) | low;
}

DecodedValue decodeChannel(const ChannelSpec& channel, std::span<const std::uint16_t> words) {
    DecodedValue out;
    out.raw = rawBits(channel, words);
    double raw = 0;
    switch (channel.type) {
        case ValueType::Int16:
            raw = std::int16_t(std::uint16_t(out.raw));
            break;
        case ValueType::UInt16:
            raw = std::uint16_t(out.raw);
            break;
        case ValueType::Int32:
            raw = std::int32_t(out.raw);
            break;
        case ValueType::UInt32:
            raw = out.raw;
            break;
        case ValueType::Float32:
            raw = std::bit_cast<float>(out.raw);
            break;
    }
    const bool listed = std::find(channel.invalid_raw.begin(), channel.invalid_raw.end(),
                                  out.raw) != channel.invalid_raw.end();
    if (listed || !std::isfinite(raw)) {
        out.status = DecodeStatus::InvalidRaw;
        out.value = std::numeric_limits<double>::quiet_NaN();
        return out;
    }
    out.value = channel.to_celsius.apply(raw * channel.scale + channel.offset);
    return out;
}

QString toString(RegisterKind kind) {
    return kind == RegisterKind::Holding ? QStringLiteral("holding") : QStringLiteral("input");
}

QString toString(ValueType type) {
    static const char* names[] = {"int16", "uint16", "int32", "uint32", "float32"};
    return QString::fromLatin1(names[int(type)]);
}

}  // namespace driftlab::devices
