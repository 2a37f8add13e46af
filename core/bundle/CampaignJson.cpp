#include "core/bundle/CampaignJson.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/bundle/BundleError.h"
#include "core/domain/MessageText.h"

namespace driftlab::bundle {
namespace {

/// What the format does when one of its keys is absent.
enum class KeyUse {
    Required,   ///< refuses the campaign
    Defaulted,  ///< a physical value (or object) falls back to a default: results change
    Optional,   ///< nothing is read (a location, a description)
};

struct FormatKey {
    FormatKey(QString name, KeyUse use = KeyUse::Optional, QString fallback = {})
        : name(std::move(name)), use(use), fallback(std::move(fallback)) {}
    QString name;
    KeyUse use;
    QString fallback;  ///< what a Defaulted key falls back to, for the message
};

/// What an unknown key is taken for when it is close to none of the format's.
enum class OtherKeys {
    Kept,    ///< top level: another tool's data, kept in `extra` without a word
    Warned,  ///< inside an object of the format: kept, with a warning
};

/// The number of single-character edits (insertions, deletions, substitutions
/// and swaps of two neighbours) between two keys, letter case ignored.
int editDistance(const QString& a, const QString& b) {
    const QString x = a.toLower(), y = b.toLower();
    std::vector<std::vector<int>> d(std::size_t(x.size()) + 1,
                                    std::vector<int>(std::size_t(y.size()) + 1));
    for (qsizetype i = 0; i <= x.size(); ++i) d[i][0] = int(i);
    for (qsizetype j = 0; j <= y.size(); ++j) d[0][j] = int(j);
    for (qsizetype i = 1; i <= x.size(); ++i)
        for (qsizetype j = 1; j <= y.size(); ++j) {
            int best = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                                 d[i - 1][j - 1] + (x[i - 1] == y[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && x[i - 1] == y[j - 2] && x[i - 2] == y[j - 1])
                best = std::min(best, d[i - 2][j - 2] + 1);
            d[i][j] = best;
        }
    return d[std::size_t(x.size())][std::size_t(y.size())];
}

/// The format's key that `key` most likely misspells: one or two edits away
/// (one for keys of three letters or fewer), or the key without its unit
/// ("travel" for travel_mm); none when no key is that close.
const FormatKey* misspelledKey(const QString& key, const std::vector<FormatKey>& keys) {
    const FormatKey* nearest = nullptr;
    int nearestDistance = 0;
    for (const FormatKey& known : keys) {
        const int limit = std::min(key.size(), known.name.size()) <= 3 ? 1 : 2;
        const bool withoutUnit = known.name.startsWith(key + QLatin1Char('_'), Qt::CaseInsensitive);
        // Keys whose lengths differ by more are further apart: a key of a
        // million characters costs no table of a million rows.
        if (!withoutUnit && std::abs(key.size() - known.name.size()) > limit) continue;
        const int distance = withoutUnit ? limit : editDistance(key, known.name);
        if (distance <= limit && (!nearest || distance < nearestDistance)) {
            nearest = &known;
            nearestDistance = distance;
        }
    }
    return nearest;
}

/// Reads the keys of one JSON object, remembering which were used so the rest
/// can be kept as `extra`. Errors name the key path, e.g. channels[2].role.
class ObjectReader {
public:
    ObjectReader(QJsonObject object, QString path, QString file, QStringList* warnings)
        : m_object(std::move(object)),
          m_path(std::move(path)),
          m_file(std::move(file)),
          m_warnings(warnings) {}

    /// Checks the object's keys against the format's `keys` before any is read.
    /// A key that misspells one of them (alpha_perK for alpha_per_K) is refused
    /// when the key it means is absent and required, or would fall back to a
    /// default: the campaign would be read with a value the user did not give.
    /// Otherwise it is kept in `extra`, and named in a warning; so is any other
    /// key unless `others` keeps it without a word.
    void checkKeys(const std::vector<FormatKey>& keys, OtherKeys others) const {
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            const QString& key = it.key();
            if (std::any_of(keys.begin(), keys.end(),
                            [&](const FormatKey& k) { return k.name == key; }))
                continue;
            const QString path = keyPath(shownText(key));
            const FormatKey* meant = misspelledKey(key, keys);
            if (meant && !has(meant->name) && meant->use != KeyUse::Optional)
                throw BundleException({m_file, 0, 0,
                                       QStringLiteral("%1: unknown key (did you mean '%2'?%3)")
                                           .arg(path, meant->name,
                                                meant->use == KeyUse::Defaulted
                                                    ? QStringLiteral(" without it, %1 would be %2")
                                                          .arg(meant->name, meant->fallback)
                                                    : QString())});
            if (!m_warnings || (!meant && others == OtherKeys::Kept)) continue;
            QStringList names;
            for (const FormatKey& k : keys) names << k.name;
            *m_warnings << QStringLiteral("%1: %2: unknown key, kept as is (%3)")
                               .arg(m_file, path,
                                    meant ? QStringLiteral("did you mean '%1'?").arg(meant->name)
                                          : QStringLiteral("the format's keys here: %1")
                                                .arg(names.join(QStringLiteral(", "))));
        }
    }

    [[noreturn]] void fail(const QString& key, const QString& message) const {
        throw BundleException({m_file, 0, 0, keyPath(key) + QStringLiteral(": ") + message});
    }
    QString keyPath(const QString& key) const {
        return m_path.isEmpty() ? key : m_path + QLatin1Char('.') + key;
    }
    bool has(const QString& key) const { return m_object.contains(key); }

    QJsonValue take(const QString& key) {
        m_used.insert(key);
        return m_object.value(key);
    }
    QString string(const QString& key, bool required) {
        QJsonValue v = take(key);
        if (v.isUndefined() && !required) return {};
        if (!v.isString())
            fail(key,
                 v.isUndefined() ? QStringLiteral("missing") : QStringLiteral("expected a string"));
        return v.toString();
    }
    std::optional<double> optionalNumber(const QString& key) {
        QJsonValue v = take(key);
        if (v.isUndefined()) return std::nullopt;
        if (!v.isDouble()) {
            bool isNumber = false;
            v.toString().toDouble(&isNumber);
            fail(key, isNumber ? QStringLiteral("expected a number, found the text \"%1\" "
                                                "(write a number without quotes)")
                                     .arg(shownText(v.toString()))
                               : QStringLiteral("expected a number"));
        }
        return v.toDouble();
    }
    double number(const QString& key) {
        auto v = optionalNumber(key);
        if (!v) fail(key, QStringLiteral("missing"));
        return *v;
    }
    double positive(const QString& key) {
        double v = number(key);
        if (!(v > 0)) fail(key, QStringLiteral("must be positive, got %1").arg(v));
        return v;
    }
    double positiveOr(const QString& key, double fallback) {
        if (!has(key)) return fallback;
        return positive(key);
    }
    std::optional<RangeMm> optionalRange(const QString& key) {
        QJsonValue v = take(key);
        if (v.isUndefined()) return std::nullopt;
        QJsonArray a = v.toArray();
        if (!v.isArray() || a.size() != 2 || !a[0].isDouble() || !a[1].isDouble())
            fail(key, QStringLiteral("expected [from_mm, to_mm]"));
        // A stroke written from its far end ([490, 210]) is the same range.
        const double first = a[0].toDouble(), second = a[1].toDouble();
        return RangeMm{std::min(first, second), std::max(first, second)};
    }
    ObjectReader object(const QString& key) {
        QJsonValue v = take(key);
        if (!v.isObject())
            fail(key, v.isUndefined() ? QStringLiteral("missing")
                                      : QStringLiteral("expected an object"));
        return ObjectReader(v.toObject(), keyPath(key), m_file, m_warnings);
    }
    QJsonArray array(const QString& key) {
        QJsonValue v = take(key);
        if (!v.isArray())
            fail(key,
                 v.isUndefined() ? QStringLiteral("missing") : QStringLiteral("expected an array"));
        return v.toArray();
    }
    QJsonObject rest() const {
        QJsonObject extra;
        for (auto it = m_object.begin(); it != m_object.end(); ++it)
            if (!m_used.contains(it.key())) extra.insert(it.key(), it.value());
        return extra;
    }

private:
    QJsonObject m_object;
    QString m_path;
    QString m_file;
    QStringList* m_warnings;
    QSet<QString> m_used;
};

ObjectReader elementReader(const QJsonArray& array, int i, const QString& name, const QString& file,
                           QStringList* warnings) {
    QString path = QStringLiteral("%1[%2]").arg(name).arg(i);
    if (!array[i].isObject())
        throw BundleException({file, 0, 0, path + QStringLiteral(": expected an object")});
    return ObjectReader(array[i].toObject(), path, file, warnings);
}

/// What no `part` can be (e.g. "ball screw's"): a value in another unit (m for
/// mm, g/cm³ for kg/m³, kJ for J), which the models would take at its word.
void requirePlausible(const ObjectReader& r, const char* key, double value, double low, double high,
                      const char* unit, const char* part) {
    if (value < low || value > high)
        r.fail(QLatin1String(key),
               QStringLiteral("%1 %2 is no %3 (%4…%5 %2): another unit?")
                   .arg(numberText(value), QString::fromUtf8(unit), QString::fromUtf8(part),
                        numberText(low), numberText(high)));
}

Screw readScrew(ObjectReader r) {
    Screw s;
    const auto per = [](double value, const char* unit) {
        return numberText(value) + QLatin1Char(' ') + QString::fromUtf8(unit);
    };
    r.checkKeys(
        {{QStringLiteral("length_mm"), KeyUse::Required},
         {QStringLiteral("diameter_mm"), KeyUse::Required},
         {QStringLiteral("lead_mm"), KeyUse::Required},
         {QStringLiteral("fixed_end_mm"), KeyUse::Required},
         {QStringLiteral("mounting"), KeyUse::Defaulted, QStringLiteral("fixed-free")},
         {QStringLiteral("alpha_per_K"), KeyUse::Defaulted, per(s.alpha_per_K, "per K")},
         {QStringLiteral("density_kg_m3"), KeyUse::Defaulted, per(s.density_kg_m3, "kg/m³")},
         {QStringLiteral("specific_heat_J_kgK"), KeyUse::Defaulted,
          per(s.specific_heat_J_kgK, "J/(kg·K)")},
         {QStringLiteral("conductivity_W_mK"), KeyUse::Defaulted,
          per(s.conductivity_W_mK, "W/(m·K)")}},
        OtherKeys::Warned);
    s.length_mm = r.positive(QStringLiteral("length_mm"));
    s.diameter_mm = r.positive(QStringLiteral("diameter_mm"));
    s.lead_mm = r.positive(QStringLiteral("lead_mm"));
    s.fixed_end_mm = r.number(QStringLiteral("fixed_end_mm"));
    s.mounting = r.string(QStringLiteral("mounting"), false);
    if (s.mounting.isEmpty()) s.mounting = QStringLiteral("fixed-free");
    s.mounting = s.mounting.trimmed().toLower();  // "Fixed-Free" as hand-written
    static const QStringList mountings{QStringLiteral("fixed-free"),
                                       QStringLiteral("fixed-supported"),
                                       QStringLiteral("fixed-fixed")};
    if (!mountings.contains(s.mounting))
        r.fail(QStringLiteral("mounting"),
               QStringLiteral("unknown mounting %1 (expected %2)")
                   .arg(quotedText(s.mounting), mountings.join(QStringLiteral(", "))));
    s.alpha_per_K = r.positiveOr(QStringLiteral("alpha_per_K"), s.alpha_per_K);
    if (s.alpha_per_K > 1e-3)
        r.fail(QStringLiteral("alpha_per_K"),
               QStringLiteral("%1 per K is not a metal's expansion coefficient; give it per kelvin "
                              "(steel: 11.5e-6), not in ppm or µm/m")
                   .arg(s.alpha_per_K));
    s.density_kg_m3 = r.positiveOr(QStringLiteral("density_kg_m3"), s.density_kg_m3);
    s.specific_heat_J_kgK =
        r.positiveOr(QStringLiteral("specific_heat_J_kgK"), s.specific_heat_J_kgK);
    s.conductivity_W_mK = r.positiveOr(QStringLiteral("conductivity_W_mK"), s.conductivity_W_mK);
    const struct {
        const char* key;
        double value, low, high;
        const char* unit;
    } limits[] = {
        {"length_mm", s.length_mm, 20, 30000, "mm"},
        {"diameter_mm", s.diameter_mm, 2, 500, "mm"},
        {"lead_mm", s.lead_mm, 0.5, 200, "mm"},
        {"density_kg_m3", s.density_kg_m3, 1000, 25000, "kg/m³"},
        {"specific_heat_J_kgK", s.specific_heat_J_kgK, 100, 5000, "J/(kg·K)"},
        {"conductivity_W_mK", s.conductivity_W_mK, 0.1, 1000, "W/(m·K)"},
    };
    for (const auto& l : limits)
        requirePlausible(r, l.key, l.value, l.low, l.high, l.unit, "ball screw's");
    s.extra = r.rest();
    return s;
}

Channel readChannel(ObjectReader r) {
    Channel c;
    r.checkKeys({{QStringLiteral("id"), KeyUse::Required},
                 {QStringLiteral("quantity"), KeyUse::Required},
                 {QStringLiteral("role"), KeyUse::Required},
                 {QStringLiteral("location")},
                 {QStringLiteral("position_mm")}},
                OtherKeys::Warned);
    c.id = r.string(QStringLiteral("id"), true);
    if (!isValidIdentifier(c.id) || isAxisColumn(c.id) || c.id == QLatin1String("run") ||
        c.id == QLatin1String("time_s"))
        r.fail(QStringLiteral("id"), QStringLiteral("%1 is not a valid channel id ([A-Za-z0-9_]+, "
                                                    "not run, time_s or an axis column)")
                                         .arg(quotedText(c.id)));
    QString quantity = r.string(QStringLiteral("quantity"), true);
    auto q = quantityFromString(quantity);
    if (!q)
        r.fail(QStringLiteral("quantity"),
               QStringLiteral("unknown quantity %1 (expected temperature, displacement or speed)")
                   .arg(quotedText(quantity)));
    c.quantity = *q;
    QString role = r.string(QStringLiteral("role"), true);
    auto ro = roleFromString(role);
    if (!ro || !roleAllowedFor(c.quantity, *ro))
        r.fail(
            QStringLiteral("role"),
            QStringLiteral("unknown role %1 for a %2 channel (expected %3)")
                .arg(quotedText(role), toString(*q), roleNamesFor(*q).join(QStringLiteral(", "))));
    c.role = *ro;
    c.location = r.string(QStringLiteral("location"), false);
    c.position_mm = r.optionalNumber(QStringLiteral("position_mm"));
    c.extra = r.rest();
    return c;
}

Run readRun(ObjectReader r) {
    Run run;
    // `procedure`: the procedure a run logged by DriftLab followed, kept in `extra`.
    r.checkKeys({{QStringLiteral("id"), KeyUse::Required},
                 {QStringLiteral("kind"), KeyUse::Required},
                 {QStringLiteral("feed_mm_min")},
                 {QStringLiteral("range_mm")},
                 {QStringLiteral("description")},
                 {QStringLiteral("procedure")},
                 // When the run took place, kept in `extra` (docs/history.md).
                 {QStringLiteral("date")},
                 {QStringLiteral("started_at")},
                 {QStringLiteral("start_date")},
                 {QStringLiteral("created_at")}},
                OtherKeys::Warned);
    run.id = r.string(QStringLiteral("id"), true);
    if (!isValidIdentifier(run.id))
        r.fail(QStringLiteral("id"),
               QStringLiteral("%1 is not a valid run id ([A-Za-z0-9_]+)").arg(quotedText(run.id)));
    QString kind = r.string(QStringLiteral("kind"), true);
    auto k = runKindFromString(kind);
    if (!k)
        r.fail(QStringLiteral("kind"),
               QStringLiteral("unknown run kind %1 (expected moving, spindle, etve or positioning)")
                   .arg(quotedText(kind)));
    run.kind = *k;
    run.feed_mm_min = r.optionalNumber(QStringLiteral("feed_mm_min"));
    run.range_mm = r.optionalRange(QStringLiteral("range_mm"));
    run.description = r.string(QStringLiteral("description"), false);
    run.extra = r.rest();
    return run;
}

}  // namespace

Campaign campaignFromJson(const QByteArray& json, const QString& fileName, QStringList* warnings) {
    QJsonParseError parseError;
    QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        QByteArray before = json.left(parseError.offset);
        int line = int(before.count('\n')) + 1;
        int column = int(parseError.offset - (before.lastIndexOf('\n') + 1)) + 1;
        const QByteArray at = json.mid(std::max(0, int(parseError.offset) - 2), 4);
        const bool comment = at.contains("//") || at.contains("/*");
        throw BundleException(
            {fileName, line, column,
             parseError.errorString() +
                 (comment ? QStringLiteral(" (JSON has no comments)") : QString())});
    }
    if (!doc.isObject())
        throw BundleException({fileName, 1, 1, QStringLiteral("expected a JSON object")});

    ObjectReader r(doc.object(), QString(), fileName, warnings);
    Campaign c;
    // The format key tells a bundle from any other JSON file; a hand-written
    // file may lack it, so the error gives the line to add.
    QString format = r.string(QStringLiteral("format"), false);
    if (format != kCampaignFormat)
        r.fail(QStringLiteral("format"),
               format.isEmpty()
                   ? QStringLiteral("missing (a campaign.json names its format: \"format\": "
                                    "\"%1\")")
                         .arg(kCampaignFormat)
                   : QStringLiteral("unsupported format %1 (expected %2)")
                         .arg(quotedText(format), kCampaignFormat));
    // Keys of other tools stay in `extra` without a word; only one that
    // misspells a key of the format is said.
    const QString absent = QStringLiteral("absent");
    r.checkKeys({{QStringLiteral("format"), KeyUse::Required},
                 {QStringLiteral("name"), KeyUse::Required},
                 {QStringLiteral("machine"), KeyUse::Required},
                 {QStringLiteral("screw"), KeyUse::Defaulted, absent},
                 {QStringLiteral("nut_length_mm"), KeyUse::Defaulted, absent},
                 {QStringLiteral("travel_mm"), KeyUse::Defaulted, absent},
                 {QStringLiteral("interferometer"), KeyUse::Defaulted, absent},
                 {QStringLiteral("channels"), KeyUse::Required},
                 {QStringLiteral("runs"), KeyUse::Required},
                 // When the campaign took place, kept in `extra` (docs/history.md).
                 {QStringLiteral("date")},
                 {QStringLiteral("started_at")},
                 {QStringLiteral("start_date")},
                 {QStringLiteral("created_at")}},
                OtherKeys::Kept);
    c.name = r.string(QStringLiteral("name"), true);

    ObjectReader machine = r.object(QStringLiteral("machine"));
    machine.checkKeys({{QStringLiteral("name"), KeyUse::Required},
                       {QStringLiteral("axis")},
                       {QStringLiteral("controller")}},
                      OtherKeys::Warned);
    c.machine.name = machine.string(QStringLiteral("name"), true);
    c.machine.axis = machine.string(QStringLiteral("axis"), false);
    c.machine.controller = machine.string(QStringLiteral("controller"), false);
    c.machine.extra = machine.rest();

    if (r.has(QStringLiteral("screw"))) c.screw = readScrew(r.object(QStringLiteral("screw")));
    if (r.has(QStringLiteral("nut_length_mm")))
        c.nut_length_mm = r.positive(QStringLiteral("nut_length_mm"));
    if (c.nut_length_mm)
        requirePlausible(r, "nut_length_mm", *c.nut_length_mm, 5, 1000, "mm",
                         "ball-screw nut's length");
    c.travel_mm = r.optionalRange(QStringLiteral("travel_mm"));
    if (r.has(QStringLiteral("interferometer"))) {
        ObjectReader i = r.object(QStringLiteral("interferometer"));
        Interferometer interferometer;
        i.checkKeys({{QStringLiteral("dead_path_mm"), KeyUse::Defaulted, QStringLiteral("0 mm")},
                     {QStringLiteral("environment_compensation"), KeyUse::Defaulted,
                      QStringLiteral("true")}},
                    OtherKeys::Warned);
        interferometer.dead_path_mm = i.optionalNumber(QStringLiteral("dead_path_mm")).value_or(0);
        if (interferometer.dead_path_mm < 0)
            i.fail(QStringLiteral("dead_path_mm"), QStringLiteral("must not be negative"));
        QJsonValue comp = i.take(QStringLiteral("environment_compensation"));
        if (!comp.isUndefined() && !comp.isBool())
            i.fail(QStringLiteral("environment_compensation"),
                   QStringLiteral("expected true or false"));
        interferometer.environment_compensation = comp.toBool(true);
        interferometer.extra = i.rest();
        c.interferometer = interferometer;
    }

    QJsonArray channels = r.array(QStringLiteral("channels"));
    for (int i = 0; i < channels.size(); ++i) {
        Channel ch =
            readChannel(elementReader(channels, i, QStringLiteral("channels"), fileName, warnings));
        if (c.findChannel(ch.id))
            throw BundleException({fileName, 0, 0,
                                   QStringLiteral("channels[%1].id: duplicate channel id %2")
                                       .arg(i)
                                       .arg(quotedText(ch.id))});
        c.channels.push_back(std::move(ch));
    }
    QJsonArray runs = r.array(QStringLiteral("runs"));
    for (int i = 0; i < runs.size(); ++i) {
        Run run = readRun(elementReader(runs, i, QStringLiteral("runs"), fileName, warnings));
        if (c.findRun(run.id))
            throw BundleException({fileName, 0, 0,
                                   QStringLiteral("runs[%1].id: duplicate run id %2")
                                       .arg(i)
                                       .arg(quotedText(run.id))});
        if (isFeedAxisRun(run.kind) && (!c.screw || !c.nut_length_mm))
            throw BundleException(
                {fileName, 0, 0,
                 QStringLiteral(
                     "runs[%1]: a %2 run needs 'screw' and 'nut_length_mm' in the campaign")
                     .arg(i)
                     .arg(toString(run.kind))});
        c.runs.push_back(std::move(run));
    }
    c.extra = r.rest();
    return c;
}

QJsonObject campaignToJson(const Campaign& c) {
    auto range = [](const RangeMm& r) { return QJsonArray{r.from_mm, r.to_mm}; };
    auto merged = [](QJsonObject known, const QJsonObject& extra) {
        for (auto it = extra.begin(); it != extra.end(); ++it) known.insert(it.key(), it.value());
        return known;
    };

    QJsonObject o = c.extra;
    o[QStringLiteral("format")] = kCampaignFormat;
    o[QStringLiteral("name")] = c.name;
    QJsonObject machine{{QStringLiteral("name"), c.machine.name}};
    if (!c.machine.axis.isEmpty()) machine[QStringLiteral("axis")] = c.machine.axis;
    if (!c.machine.controller.isEmpty())
        machine[QStringLiteral("controller")] = c.machine.controller;
    o[QStringLiteral("machine")] = merged(machine, c.machine.extra);
    if (c.screw) {
        const Screw& s = *c.screw;
        o[QStringLiteral("screw")] =
            merged(QJsonObject{{QStringLiteral("length_mm"), s.length_mm},
                               {QStringLiteral("diameter_mm"), s.diameter_mm},
                               {QStringLiteral("lead_mm"), s.lead_mm},
                               {QStringLiteral("fixed_end_mm"), s.fixed_end_mm},
                               {QStringLiteral("mounting"), s.mounting},
                               {QStringLiteral("alpha_per_K"), s.alpha_per_K},
                               {QStringLiteral("density_kg_m3"), s.density_kg_m3},
                               {QStringLiteral("specific_heat_J_kgK"), s.specific_heat_J_kgK},
                               {QStringLiteral("conductivity_W_mK"), s.conductivity_W_mK}},
                   s.extra);
    }
    if (c.nut_length_mm) o[QStringLiteral("nut_length_mm")] = *c.nut_length_mm;
    if (c.travel_mm) o[QStringLiteral("travel_mm")] = range(*c.travel_mm);
    if (c.interferometer)
        o[QStringLiteral("interferometer")] =
            merged(QJsonObject{{QStringLiteral("dead_path_mm"), c.interferometer->dead_path_mm},
                               {QStringLiteral("environment_compensation"),
                                c.interferometer->environment_compensation}},
                   c.interferometer->extra);

    QJsonArray channels;
    for (const Channel& ch : c.channels) {
        QJsonObject j{{QStringLiteral("id"), ch.id},
                      {QStringLiteral("quantity"), toString(ch.quantity)},
                      {QStringLiteral("role"), toString(ch.role)}};
        if (!ch.location.isEmpty()) j[QStringLiteral("location")] = ch.location;
        if (ch.position_mm) j[QStringLiteral("position_mm")] = *ch.position_mm;
        channels.append(merged(j, ch.extra));
    }
    o[QStringLiteral("channels")] = channels;

    QJsonArray runs;
    for (const Run& run : c.runs) {
        QJsonObject j{{QStringLiteral("id"), run.id}, {QStringLiteral("kind"), toString(run.kind)}};
        if (run.feed_mm_min) j[QStringLiteral("feed_mm_min")] = *run.feed_mm_min;
        if (run.range_mm) j[QStringLiteral("range_mm")] = range(*run.range_mm);
        if (!run.description.isEmpty()) j[QStringLiteral("description")] = run.description;
        runs.append(merged(j, run.extra));
    }
    o[QStringLiteral("runs")] = runs;
    return o;
}

}  // namespace driftlab::bundle
