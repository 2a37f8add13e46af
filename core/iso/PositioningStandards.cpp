#include "core/iso/PositioningStandards.h"

#include <algorithm>
#include <cmath>

namespace driftlab::iso {
namespace {

struct StandardInfo {
    PositioningStandard standard;
    const char* id;
    const char* title;
};

constexpr StandardInfo kStandards[] = {
    {PositioningStandard::Iso230_2_2014, "iso230-2:2014", "ISO 230-2:2014"},
    {PositioningStandard::Iso230_2_2006, "iso230-2:2006", "ISO 230-2:2006"},
    {PositioningStandard::Iso230_2_1997, "iso230-2:1997", "ISO 230-2:1997"},
    {PositioningStandard::GbT17421_2_2016, "gbt17421.2", "GB/T 17421.2-2016"},
    {PositioningStandard::JisB0182_1993, "jis-b0182", "JIS B 0182:1993"},
};

const StandardInfo& infoOf(PositioningStandard standard) {
    for (const StandardInfo& info : kStandards)
        if (info.standard == standard) return info;
    return kStandards[0];
}

/// The ISO 230-2 evaluation of readings, edition and k of the standard.
Evaluation isoEvaluation(const std::vector<Reading>& readings, Edition edition, double k,
                         const Settings& base) {
    Settings settings = base;
    settings.edition = edition;
    settings.coverage_factor = k;
    return evaluate(readings, settings);
}

void copyCounts(const Evaluation& from, StandardEvaluation& to) {
    to.error = from.error;
    to.targets = int(from.targets.size());
    to.cycles = from.cycles;
}

/// The twelve axis values of ISO 230-2, as `iso230-2 --json` names them.
std::vector<StandardValue> isoValues(const AxisResult& a) {
    std::vector<StandardValue> values;
    for (const AxisValue& v : axisValues())
        values.push_back({QString::fromUtf8(v.key), QString::fromUtf8(v.symbol),
                          QString::fromUtf8(v.meaning), a.*v.value});
    return values;
}

StandardEvaluation evaluateIso(const std::vector<Reading>& readings, PositioningStandard standard,
                               Edition edition, const Settings& base) {
    StandardEvaluation result;
    result.standard = standard;
    result.coverage_factor = 2;
    // ISO 230-2 asks for five approaches per direction at every target on an
    // axis up to 2000 mm (docs/iso230.md).
    result.min_approaches = 5;
    result.definitions = QStringLiteral(
        "k = 2: R↑_i = 4·s↑_i, R_i = max(2·s↑_i + 2·s↓_i + |B_i|, R↑_i, R↓_i), A from x̄ ± 2·s");
    const Evaluation e = isoEvaluation(readings, edition, result.coverage_factor, base);
    copyCounts(e, result);
    if (!e.ok()) return result;
    result.values = isoValues(e.axis);
    result.skipped = e.skipped;
    result.warnings = e.warnings;
    return result;
}

/// JIS B 0182:1993 is a vocabulary: it defines the reversal value at a target
/// (term 342, x̄↑_i − x̄↓_i) and the bidirectional repeatability at a target
/// (term 346, the largest of 3s↑_i + 3s↓_i + |B_i|, 6s↑_i and 6s↓_i), which
/// are ISO 230-2's B_i and R_i with k = 3. It states no minimum of approaches
/// and no axis value: the axis values here are the largest over the targets.
StandardEvaluation evaluateJisB0182(const std::vector<Reading>& readings, const Settings& base) {
    StandardEvaluation result;
    result.standard = PositioningStandard::JisB0182_1993;
    result.coverage_factor = 3;
    result.min_approaches = 0;
    result.definitions = QStringLiteral(
        "k = 3: B_i = x̄↑_i − x̄↓_i, R_i = max(3·s↑_i + 3·s↓_i + |B_i|, 6·s↑_i, 6·s↓_i); "
        "the axis values are the largest over the targets");
    const Evaluation e = isoEvaluation(readings, Edition::Iso2014, result.coverage_factor, base);
    copyCounts(e, result);
    if (!e.ok()) return result;
    result.values = {
        {"B", "B", "reversal value, largest |B_i|", e.axis.reversal_um},
        {"R", "R", "bidirectional repeatability, largest R_i", e.axis.r_um},
    };
    if (!e.skipped.isEmpty())
        result.skipped << QStringLiteral(
            "R not determined: a target has one reading in a direction, and s needs two");
    // ISO 230-2's minimums are not this vocabulary's; the drift and repeated
    // reading warnings are about the data and stay.
    for (const QString& w : e.warnings)
        if (!w.startsWith(QStringLiteral("below ISO 230-2's minimum: "))) result.warnings << w;
    return result;
}

}  // namespace

QString standardId(PositioningStandard standard) {
    return QString::fromUtf8(infoOf(standard).id);
}

QString standardTitle(PositioningStandard standard) {
    return QString::fromUtf8(infoOf(standard).title);
}

std::optional<PositioningStandard> standardFromId(const QString& id) {
    const QString wanted = id.trimmed();
    for (const StandardInfo& info : kStandards)
        if (wanted.compare(QString::fromUtf8(info.id), Qt::CaseInsensitive) == 0)
            return info.standard;
    return std::nullopt;
}

std::optional<Edition> isoEditionOf(PositioningStandard standard) {
    switch (standard) {
        case PositioningStandard::Iso230_2_2014:
            return Edition::Iso2014;
        case PositioningStandard::Iso230_2_2006:
            return Edition::Iso2006;
        case PositioningStandard::Iso230_2_1997:
            return Edition::Iso1997;
        case PositioningStandard::GbT17421_2_2016:
        case PositioningStandard::JisB0182_1993:
            break;
    }
    return std::nullopt;
}

const std::vector<PositioningStandard>& positioningStandards() {
    static const std::vector<PositioningStandard> all = [] {
        std::vector<PositioningStandard> standards;
        for (const StandardInfo& info : kStandards) standards.push_back(info.standard);
        return standards;
    }();
    return all;
}

const std::vector<LeftOutStandard>& leftOutStandards() {
    static const std::vector<LeftOutStandard> leftOut{
        {QStringLiteral("vdi3441"), QStringLiteral("VDI/DGQ 3441"),
         QStringLiteral("laser software names its parameters (P, Ps, U, Pa), but no public "
                        "text of their formulas could be found: how x̄_j and s_j combine the "
                        "two directions and what Ps_j multiplies are not confirmed")},
        {QStringLiteral("asme-b5.54"), QStringLiteral("ASME B5.54"),
         QStringLiteral("no public text of its linear positioning formulas, coverage or "
                        "number of runs could be found")},
        {QStringLiteral("jis-b6192"), QStringLiteral("JIS B 6192"),
         QStringLiteral("neither its text nor the ISO 230-2 edition it adopts could be "
                        "confirmed")},
    };
    return leftOut;
}

const LeftOutStandard* leftOutStandard(const QString& id) {
    const QString wanted = id.trimmed();
    for (const LeftOutStandard& s : leftOutStandards())
        if (wanted.compare(s.id, Qt::CaseInsensitive) == 0) return &s;
    return nullptr;
}

const StandardValue* StandardEvaluation::value(const QString& key) const {
    for (const StandardValue& v : values)
        if (v.key == key) return &v;
    return nullptr;
}

StandardEvaluation evaluateStandard(const std::vector<Reading>& readings,
                                    PositioningStandard standard, const Settings& base) {
    if (const std::optional<Edition> edition = isoEditionOf(standard))
        return evaluateIso(readings, standard, *edition, base);
    switch (standard) {
        case PositioningStandard::Iso230_2_2014:
        case PositioningStandard::Iso230_2_2006:
        case PositioningStandard::Iso230_2_1997:
            break;
        case PositioningStandard::GbT17421_2_2016: {
            // Its catalogue scope is the ISO 230-2:2006 scope (annexes A and B,
            // uncertainties as ISO/TR 230-9:2005 Annex C), so it is evaluated
            // as that edition (docs/standards.md).
            StandardEvaluation result = evaluateIso(readings, standard, Edition::Iso2006, base);
            result.definitions += QStringLiteral(" (as ISO 230-2:2006)");
            return result;
        }
        case PositioningStandard::JisB0182_1993:
            return evaluateJisB0182(readings, base);
    }
    StandardEvaluation unknown;
    unknown.standard = standard;
    unknown.error = QStringLiteral("unknown positioning standard");
    return unknown;
}

StandardsComparison compareStandards(const std::vector<Reading>& readings, const Settings& base) {
    StandardsComparison comparison;
    for (PositioningStandard standard : positioningStandards()) {
        StandardEvaluation e = evaluateStandard(readings, standard, base);
        if (!e.ok() && comparison.ok())
            comparison.error = standardTitle(standard) + QStringLiteral(": ") + e.error;
        for (const QString& w : e.warnings)
            if (!comparison.warnings.contains(w)) comparison.warnings << w;
        comparison.evaluations.push_back(std::move(e));
    }
    return comparison;
}

std::vector<const StandardValue*> comparisonRows(const StandardsComparison& comparison) {
    std::vector<const StandardValue*> rows;
    for (const StandardEvaluation& e : comparison.evaluations)
        for (const StandardValue& v : e.values)
            if (std::none_of(rows.begin(), rows.end(),
                             [&](const StandardValue* r) { return r->key == v.key; }))
                rows.push_back(&v);
    return rows;
}

}  // namespace driftlab::iso
