#include "core/compensation/ThermalProfile.h"

#include <algorithm>

#include "core/models/AutoModel.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::compensation {
namespace {

/// Where the profile is evaluated: one point per millimetre at most, at least
/// 64, then linear in between (the heat-transfer model simulates the whole run
/// per call, so it is called once).
constexpr int kProfilePoints = 257;

double pointAt(double from_mm, double to_mm, int i) {
    return from_mm + (to_mm - from_mm) * i / (kProfilePoints - 1);
}

}  // namespace

QString ThermalStateFit::choseNone() const {
    const auto* chooser = dynamic_cast<const models::AutoModel*>(model.get());
    if (!chooser || chooser->chosen() != QLatin1String("none")) return {};
    return notes.isEmpty() ? QStringLiteral("no compensation chosen")
                           : notes.front().section(QLatin1Char(':'), 0, 0);
}

QString defaultTrainingRun(const Campaign& campaign, const QString& state_run) {
    for (const Run& run : campaign.runs)
        if (run.id != state_run && isFeedAxisRun(run.kind) && !run.positioning.empty())
            return run.id;
    return {};
}

ThermalStateFit fitThermalState(const Campaign& campaign, const ThermalStateOptions& options) {
    models::DatasetResult data =
        models::buildDataset(campaign, options.train_runs + QStringList{options.state_run});
    if (!data.ok()) throw ServiceError(data.error);
    ThermalStateFit fit;
    fit.state = data.runs.back();
    data.runs.pop_back();
    fit.training = std::move(data.runs);
    fit.train_runs = options.train_runs;
    fit.state_run = options.state_run;
    fit.time_s = options.time_s;
    double end_s = 0;
    for (const auto& o : fit.state.observations) end_s = std::max(end_s, o.time_s);
    if (!fit.state.motion.empty()) end_s = std::max(end_s, fit.state.motion.back().end_s);
    if (options.time_s > end_s)
        throw ServiceError(QStringLiteral("run %1 ends at %2 s, before %3 s")
                               .arg(options.state_run)
                               .arg(end_s)
                               .arg(options.time_s),
                           ServiceError::Kind::BadRequest);
    const QString label = QStringLiteral("fitting ") + options.model;
    if (options.progress) options.progress(label, 0);
    models::ValidatedFit validated =
        models::fitValidated(options.model, fit.training, options.cancelled);
    if (options.cancelled && options.cancelled())
        throw ServiceError(QStringLiteral("the fit was cancelled"));
    if (options.progress) options.progress(label, 1);
    if (!validated.fit.success) throw ServiceError(validated.fit.message);
    fit.model = std::move(validated.model);
    fit.notes = validated.fit.notes;
    fit.validation = validated.validation;
    fit.gaps = models::gapsOf(fit.training);
    fit.gaps.insert(fit.gaps.end(), fit.state.gaps.begin(), fit.state.gaps.end());
    return fit;
}

ThermalProfile thermalProfile(const ThermalStateFit& fit, double from_mm, double to_mm) {
    ThermalProfile profile;
    profile.validation = fit.validation;
    // The state's run beyond the training runs' rises is an extrapolation.
    profile.uncertainty_um = [interval = fit.validation.interval,
                              beyond = models::beyondTraining(fit.training, fit.state)](double x) {
        return interval.known() ? interval.halfWidthAt(x, beyond) : 0.0;
    };
    profile.from_mm = from_mm;
    profile.to_mm = to_mm;
    profile.fixed_end_mm = fit.state.fixedEnd_mm();
    std::vector<models::PredictionPoint> points;
    for (int i = 0; i < kProfilePoints; ++i)
        points.push_back({fit.time_s, pointAt(from_mm, to_mm, i)});
    const models::Prediction predicted = fit.model->predict(fit.state, points);
    if (!predicted.ok()) throw ServiceError(predicted.error);
    std::vector<double> x_mm, e_um;
    for (std::size_t i = 0; i < points.size(); ++i) {
        x_mm.push_back(points[i].position_mm);
        e_um.push_back(predicted.error_um[i]);
    }
    profile.error_um = [x_mm, e_um](double x) {
        if (x <= x_mm.front()) return e_um.front();
        if (x >= x_mm.back()) return e_um.back();
        const auto hi = std::size_t(std::upper_bound(x_mm.begin(), x_mm.end(), x) - x_mm.begin());
        const double f = (x - x_mm[hi - 1]) / (x_mm[hi] - x_mm[hi - 1]);
        return e_um[hi - 1] + f * (e_um[hi] - e_um[hi - 1]);
    };
    profile.description =
        QStringLiteral("%1 fitted on %2, at %3 t = %4 s")
            .arg(fit.model->name(), fit.train_runs.join(QLatin1Char(',')), fit.state_run)
            .arg(fit.time_s);
    return profile;
}

ErrorLine thermalErrorLine(const ThermalProfile& profile, double reference_mm) {
    std::vector<double> x_mm, e_um;
    for (int i = 0; i < kProfilePoints; ++i) {
        x_mm.push_back(pointAt(profile.from_mm, profile.to_mm, i));
        e_um.push_back(profile.error_um(x_mm.back()));
    }
    return fitErrorLine(x_mm, e_um, reference_mm);
}

}  // namespace driftlab::compensation
