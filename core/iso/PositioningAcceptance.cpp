#include "core/iso/PositioningAcceptance.h"

#include <algorithm>
#include <cmath>

#include "core/domain/MessageText.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::iso {

Verdict PositioningAcceptance::overall() const {
    if (decisions.empty()) return Verdict::NotDetermined;
    const auto any = [this](Verdict v) {
        return std::any_of(decisions.begin(), decisions.end(),
                           [v](const Decision& d) { return d.verdict == v; });
    };
    if (any(Verdict::Fail)) return Verdict::Fail;
    if (any(Verdict::NotProven) || any(Verdict::NotDetermined)) return Verdict::NotProven;
    return Verdict::Pass;
}

namespace {

ChannelRole driftRoleOf(const QString& axis) {
    const QString a = axis.trimmed().toUpper();
    if (a == QLatin1String("X")) return ChannelRole::DriftX;
    if (a == QLatin1String("Y")) return ChannelRole::DriftY;
    if (a == QLatin1String("Z")) return ChannelRole::DriftZ;
    return ChannelRole::Drift;
}

/// The largest max − min of `series` over windows [t_i, t_i + window_s].
double largestWindowRange(const DriftSeries& series, double window_s) {
    double largest = 0;
    const auto& t = series.time_s;
    const auto& x = series.drift_um;
    std::size_t end = 0;
    for (std::size_t start = 0; start < t.size(); ++start) {
        end = std::max(end, start);
        while (end + 1 < t.size() && t[end + 1] - t[start] <= window_s) ++end;
        const auto [low, high] =
            std::minmax_element(x.begin() + long(start), x.begin() + long(end) + 1);
        largest = std::max(largest, *high - *low);
        if (end + 1 == t.size()) break;  // later windows are inside this one
    }
    return largest;
}

}  // namespace

std::optional<double> environmentalVariationError(const Campaign& campaign, const Run& etve,
                                                  const QString& axis, double duration_s,
                                                  QString* source, QString* error) {
    const ProbeDriftEvaluation drift = evaluateProbeDrift(campaign, etve);
    if (!drift.ok() || drift.probes.empty()) {
        if (error)
            *error = QStringLiteral("ETVE run %1 gives no environmental variation error: %2")
                         .arg(quotedText(etve.id),
                              drift.ok() ? QStringLiteral("it has no drift probe") : drift.error);
        return std::nullopt;
    }
    std::vector<const ProbeDrift*> chosen;
    for (ChannelRole role : {driftRoleOf(axis), ChannelRole::Drift}) {
        for (const ProbeDrift& p : drift.probes)
            if (p.role == role) chosen.push_back(&p);
        if (!chosen.empty()) break;
    }
    if (chosen.empty())
        for (const ProbeDrift& p : drift.probes) chosen.push_back(&p);
    double eve_um = 0;
    QString probe;
    for (const ProbeDrift* p : chosen) {
        const double range_um = largestWindowRange(p->drift, duration_s);
        if (range_um >= eve_um) eve_um = range_um, probe = p->channel_id;
    }
    if (source)
        *source = QStringLiteral("ETVE run %1, probe %2, largest range over %3 min")
                      .arg(quotedText(etve.id), quotedText(probe))
                      .arg(QString::number(duration_s / 60, 'f', 0));
    return eve_um;
}

PositioningAcceptance evaluateAcceptance(const Campaign& campaign, const Run& run,
                                         const AcceptanceSpecification& spec,
                                         const Settings& settings) {
    PositioningAcceptance result;
    result.run_id = run.id;
    result.axis = campaign.machine.axis;
    const auto fail = [&result](const QString& why) {
        result.error = QStringLiteral("run %1: %2").arg(quotedText(result.run_id), why);
        return result;
    };

    QString error;
    const QStringList materials = materialChannels(campaign, spec.temperature, &error);
    if (!error.isEmpty()) return fail(error);
    result.environment = testEnvironment(campaign, run, materials);
    const auto readings =
        readingsAt20C(campaign, run, spec.temperature, materials, &result.normalisation, &error);
    if (!readings) return fail(error);
    result.readings = *readings;
    result.evaluation = evaluate(result.readings, settings);
    if (!result.evaluation.ok()) return fail(result.evaluation.error);

    UncertaintyConditions conditions;
    const auto& targets = result.evaluation.targets;
    conditions.length_mm = targets.back().target_mm - targets.front().target_mm;
    conditions.expansion_per_K =
        result.normalisation.expansion_per_K > 0 ? result.normalisation.expansion_per_K
        : spec.temperature.expansion_per_K       ? *spec.temperature.expansion_per_K
        : campaign.screw                         ? campaign.screw->alpha_per_K
                                                 : 11.5e-6;
    if (result.normalisation.mode == Normalisation::Mode::Normalised)
        conditions.material_temperature_C = result.normalisation.mean_material_C;
    else if (result.environment.material)
        conditions.material_temperature_C = result.environment.material->mean_C;
    else if (spec.temperature.material_temperature_C)
        conditions.material_temperature_C = *spec.temperature.material_temperature_C;
    if (result.environment.air) conditions.air.temperature_C = result.environment.air->mean_C;

    const SetupUncertainty& setup = spec.uncertainty;
    if (setup.eve_um) {
        conditions.eve_um = *setup.eve_um;
        conditions.eve_source = QStringLiteral("the specification's eve_um");
    } else {
        const Run* etve = nullptr;
        if (!setup.eve_run.isEmpty()) {
            etve = campaign.findRun(setup.eve_run);
            if (!etve || etve->kind != RunKind::Etve)
                return fail(QStringLiteral("uncertainty.eve_run %1 is not an ETVE run of the "
                                           "campaign")
                                .arg(quotedText(setup.eve_run)));
        } else {
            // One drift test at rest in the campaign is the one the lab ran for it.
            int count = 0;
            for (const Run& r : campaign.runs)
                if (r.kind == RunKind::Etve) etve = &r, ++count;
            if (count > 1) {
                etve = nullptr;
                result.notes << QStringLiteral(
                                    "%1 ETVE runs and no uncertainty.eve_run: the "
                                    "environmental variation error is not counted")
                                    .arg(count);
            }
        }
        if (etve) {
            const double duration_s =
                std::max(result.environment.end_s - result.environment.start_s, 1.0);
            const auto eve = environmentalVariationError(campaign, *etve, result.axis, duration_s,
                                                         &conditions.eve_source, &error);
            if (!eve) return fail(error);
            conditions.eve_um = *eve;
        }
    }
    result.budget = uncertaintyBudget(setup, conditions);
    if (result.normalisation.mode == Normalisation::Mode::NotNormalised &&
        std::abs(conditions.material_temperature_C - 20) > 0.5)
        result.notes << QStringLiteral(
                            "the machine was at %1 °C and the readings are not normalised: "
                            "E, M and A include about %2 µm of expansion over the travel")
                            .arg(QString::number(conditions.material_temperature_C, 'f', 2))
                            .arg(QString::number(
                                conditions.expansion_per_K *
                                    std::abs(conditions.material_temperature_C - 20) *
                                    conditions.length_mm * 1000,
                                'f', 1));

    if (const AxisTolerances* tolerances = spec.tolerancesOf(result.axis)) {
        for (const QString& key : iso230_2ParameterKeys()) {
            const auto t = tolerances->iso230_2_um.find(key);
            if (t == tolerances->iso230_2_um.end()) continue;
            result.decisions.push_back(decide(key, axisValue(result.evaluation.axis, key),
                                              result.budget.find(key)->expanded_um, t->second));
        }
    } else if (!spec.axes.empty()) {
        QStringList names;
        for (const auto& [name, axis] : spec.axes) names << name;
        result.notes << QStringLiteral(
                            "the specification has no tolerances for axis %1 (it has "
                            "%2): no verdict")
                            .arg(quotedText(result.axis), quotedList(names));
    }
    return result;
}

}  // namespace driftlab::iso
