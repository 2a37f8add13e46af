#include "core/models/ModelValidation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/domain/HeldLinear.h"
#include "core/models/AutoModel.h"
#include "core/models/ModelError.h"
#include "core/models/ModelFactory.h"
#include "core/models/TrainingEnvelope.h"

namespace driftlab::models {
namespace {

/// The run with its observations before (`early`) or after 70 % of its time.
RunData timeSplit(const RunData& run, bool early) {
    double first = run.observations.front().time_s, last = first;
    for (const ErrorObservation& o : run.observations) {
        first = std::min(first, o.time_s);
        last = std::max(last, o.time_s);
    }
    const double cut = first + 0.7 * (last - first);
    RunData part = run;
    part.observations.clear();
    for (const ErrorObservation& o : run.observations)
        if ((o.time_s <= cut) == early) part.observations.push_back(o);
    return part;
}

/// The conformal quantile of |r|: the ⌈(n + 1)·level⌉-th smallest, which
/// covers a further exchangeable reading with probability ≥ level; the
/// largest when n is too small for that.
double conformalQuantile(std::vector<double> magnitudes, double level) {
    if (magnitudes.empty()) return PredictionInterval::kNaN;
    const auto n = magnitudes.size();
    const std::size_t rank = std::min(n, std::size_t(std::ceil(double(n + 1) * level - 1e-9)));
    std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(rank - 1),
                     magnitudes.end());
    return magnitudes[rank - 1];
}

/// A positioning error's interval per target: at least this many held-out
/// readings at a target, or the pooled interval alone.
constexpr std::size_t kReadingsPerTarget = 20;
/// The interval beyond the training runs: at least this many readings of the
/// folds' extrapolations, or none.
constexpr std::size_t kReadingsBeyond = 20;

/// The conformal quantile of `magnitudes` overall and, where `byTarget` has
/// at least kReadingsPerTarget at every one of several targets, per target.
void quantiles(const std::vector<double>& magnitudes,
               const std::map<double, std::vector<double>>& byTarget, double level, double* overall,
               std::vector<double>* positions, std::vector<double>* perTarget) {
    *overall = conformalQuantile(magnitudes, level);
    bool each = byTarget.size() > 1;
    for (const auto& [x, m] : byTarget) each = each && m.size() >= kReadingsPerTarget;
    if (!each) return;
    for (const auto& [x, m] : byTarget) {
        if (positions) positions->push_back(x);
        perTarget->push_back(conformalQuantile(m, level));
    }
}

}  // namespace

void nestBeyondInterval(const std::vector<RunData>& training, PredictionInterval* interval,
                        const std::function<bool()>& cancelled) {
    std::vector<ValidationFold> extrapolating;
    for (ValidationFold& fold : validationFolds(training))
        if (std::find(fold.held_out_beyond.begin(), fold.held_out_beyond.end(), true) !=
            fold.held_out_beyond.end())
            extrapolating.push_back(std::move(fold));
    if (extrapolating.empty()) return;
    const PredictionInterval nested =
        validationOf(crossValidatedPredictions(QStringLiteral("auto"), extrapolating, cancelled),
                     training.front().positionDependent(), training.size())
            .interval;
    interval->beyond_half_width_um = nested.beyond_half_width_um;
    interval->beyond_by_position_um = nested.position_mm == interval->position_mm
                                          ? nested.beyond_by_position_um
                                          : std::vector<double>{};
    interval->beyond_readings = nested.beyond_readings;
}

std::vector<ValidationFold> validationFolds(const std::vector<RunData>& training) {
    // Folds of two kinds. Each run held out in turn scores motion the fit has
    // not seen, but fits on one run fewer: with three runs a family whose
    // strength shows only once every speed programme is in the fit ranks low
    // there. So every run's first 70 % of time is also fitted together and
    // each run's last 30 % scored (in a warm-up and cool-down test, mostly
    // the cooling): every programme in the fit, time it has not seen. With a
    // single run that is the only fold.
    std::vector<ValidationFold> folds;
    if (training.size() > 1)
        for (std::size_t r = 0; r < training.size(); ++r) {
            ValidationFold fold;
            for (std::size_t k = 0; k < training.size(); ++k)
                if (k != r) fold.fit_on.push_back(training[k]);
            fold.held_out.push_back(training[r]);
            folds.push_back(std::move(fold));
        }
    ValidationFold inTime;
    for (const RunData& run : training) {
        if (run.observations.empty()) continue;
        inTime.fit_on.push_back(timeSplit(run, true));
        RunData late = timeSplit(run, false);
        if (!late.observations.empty()) inTime.held_out.push_back(std::move(late));
    }
    if (!inTime.held_out.empty()) folds.push_back(std::move(inTime));
    for (ValidationFold& fold : folds)
        for (const RunData& part : fold.held_out)
            fold.held_out_beyond.push_back(beyondTraining(fold.fit_on, part));
    return folds;
}

QString describeValidationFolds(std::size_t trainingRuns) {
    return trainingRuns > 1 ? QStringLiteral(
                                  "leaving each training run out in turn, and fitting every "
                                  "run's first 70 % to score the rest")
                            : QStringLiteral("fitting the run's first 70 % and scoring the rest");
}

double HeldOutPredictions::rms_um() const {
    double squares = 0;
    for (std::size_t i = 0; i < measured_um.size(); ++i)
        squares += std::pow(measured_um[i] - predicted_um[i], 2);
    return measured_um.empty() ? Validation::kNaN : std::sqrt(squares / double(measured_um.size()));
}

double HeldOutPredictions::none_rms_um() const {
    double squares = 0;
    for (double m : measured_um) squares += m * m;
    return measured_um.empty() ? Validation::kNaN : std::sqrt(squares / double(measured_um.size()));
}

double HeldOutPredictions::standard_error_um() const {
    // The standard error of the mean square over the parts, carried to the
    // RMS (d√m = dm / 2√m).
    std::vector<double> meanSquares;
    std::size_t begin = 0;
    for (std::size_t end : part_ends) {
        double squares = 0;
        for (std::size_t i = begin; i < end; ++i)
            squares += std::pow(measured_um[i] - predicted_um[i], 2);
        if (end > begin) meanSquares.push_back(squares / double(end - begin));
        begin = end;
    }
    const std::size_t k = meanSquares.size();
    const double rms = rms_um();
    if (k < 2 || !(rms > 0)) return 0;
    double mean = 0, spread = 0;
    for (double m : meanSquares) mean += m / double(k);
    for (double m : meanSquares) spread += (m - mean) * (m - mean) / double(k - 1);
    return std::sqrt(spread / double(k)) / (2 * rms);
}

HeldOutPredictions crossValidatedPredictions(const QString& family,
                                             const std::vector<ValidationFold>& folds,
                                             const std::function<bool()>& cancelled) {
    if (!makeModel(family)) throw ModelError(QStringLiteral("'%1' is not a model").arg(family));
    return crossValidatedPredictions([family] { return makeModel(family); }, folds, cancelled);
}

HeldOutPredictions crossValidatedPredictions(const ModelMaker& make,
                                             const std::vector<ValidationFold>& folds,
                                             const std::function<bool()>& cancelled) {
    HeldOutPredictions out;
    for (const ValidationFold& fold : folds) {
        const std::unique_ptr<ThermalErrorModel> model = make();
        if (cancelled && cancelled())
            throw ModelError(QStringLiteral("model '%1': fit cancelled").arg(model->name()));
        if (cancelled) model->setCancelCheck(cancelled);
        const FitSummary fit = model->fit(fold.fit_on);
        if (!fit.success) throw ModelError(fit.message);
        for (std::size_t part = 0; part < fold.held_out.size(); ++part) {
            const RunData& heldOut = fold.held_out[part];
            const Prediction p = model->predict(heldOut);
            if (!p.ok()) throw ModelError(p.error);
            out.part_beyond.push_back(part < fold.held_out_beyond.size() &&
                                      fold.held_out_beyond[part]);
            for (std::size_t i = 0; i < heldOut.observations.size(); ++i) {
                out.measured_um.push_back(heldOut.observations[i].error_um);
                out.predicted_um.push_back(p.error_um[i]);
                out.position_mm.push_back(heldOut.observations[i].position_mm);
            }
            out.part_ends.push_back(out.measured_um.size());
        }
    }
    if (out.measured_um.empty()) throw ModelError(QStringLiteral("no observation to score on"));
    return out;
}

double PredictionInterval::halfWidthAt(double x_mm, bool beyond) const {
    const double within = position_mm.empty()
                              ? half_width_um
                              : heldLinearAt(position_mm, half_width_by_position_um, x_mm);
    if (!beyond || !knownBeyond()) return within;
    const double outside = beyond_by_position_um.empty()
                               ? beyond_half_width_um
                               : heldLinearAt(position_mm, beyond_by_position_um, x_mm);
    return std::max(within, outside);
}

QString extrapolationWords(const PredictionInterval& interval, bool beyond) {
    // Said only where it widens the interval.
    if (!beyond || !interval.knownBeyond() ||
        !(interval.beyond_half_width_um > interval.half_width_um))
        return {};
    return QStringLiteral(", ±%1 µm on the held-out runs beyond the training runs")
        .arg(std::max(interval.half_width_um, interval.beyond_half_width_um), 0, 'f', 2);
}

bool beyondTraining(const std::vector<RunData>& training, const RunData& run) {
    return !risesBeyondTraining(training, {run}).empty() ||
           !speedsBeyondTraining(training, {run}).empty();
}

QString Validation::describe() const {
    return QStringLiteral("cross-validated RMS %1 µm (no compensation %2 µm)")
        .arg(rms_um, 0, 'g', 3)
        .arg(none_rms_um, 0, 'g', 3);
}

QString Validation::harmReason(const QString& what) const {
    if (!worseThanNone()) return {};
    return QStringLiteral(
               "%1 does worse than no compensation where it was not fitted (%2, %3): it would "
               "make the machine worse")
        .arg(what, describe(), folds);
}

Validation validationOf(const HeldOutPredictions& p, bool positionDependent,
                        std::size_t trainingRuns) {
    Validation v;
    v.rms_um = p.rms_um();
    v.none_rms_um = p.none_rms_um();
    v.readings = p.measured_um.size();
    v.folds = describeValidationFolds(trainingRuns);
    PredictionInterval& interval = v.interval;
    std::vector<double> magnitudes, beyond;
    std::map<double, std::vector<double>> byTarget, beyondByTarget;
    std::size_t part = 0;
    for (std::size_t i = 0; i < p.measured_um.size(); ++i) {
        while (part < p.part_ends.size() && i >= p.part_ends[part]) ++part;
        const double r = std::abs(p.measured_um[i] - p.predicted_um[i]);
        const bool extrapolated = part < p.part_beyond.size() && p.part_beyond[part];
        magnitudes.push_back(r);
        if (extrapolated) beyond.push_back(r);
        if (!positionDependent) continue;
        byTarget[p.position_mm[i]].push_back(r);
        if (extrapolated) beyondByTarget[p.position_mm[i]].push_back(r);
    }
    quantiles(magnitudes, byTarget, interval.level, &interval.half_width_um, &interval.position_mm,
              &interval.half_width_by_position_um);
    const bool perTarget = !interval.position_mm.empty();
    interval.beyond_readings = beyond.size();
    if (beyond.size() >= kReadingsBeyond) {
        // Per target only where the pooled interval is, on the same targets.
        std::vector<double> perTargetBeyond;
        quantiles(beyond, perTarget ? beyondByTarget : decltype(beyondByTarget){}, interval.level,
                  &interval.beyond_half_width_um, nullptr, &perTargetBeyond);
        if (perTargetBeyond.size() == interval.position_mm.size())
            interval.beyond_by_position_um = std::move(perTargetBeyond);
    }
    interval.method = QStringLiteral(
                          "95 % of the readings the fit did not see fall within it, by "
                          "cross-validation (%1: %2 readings%3)")
                          .arg(v.folds)
                          .arg(v.readings)
                          .arg(perTarget ? QStringLiteral(", per target position") : QString());
    return v;
}

Coverage coverageOf(const ThermalErrorModel& model, const PredictionInterval& interval,
                    const std::vector<RunData>& runs, const std::vector<RunData>& training) {
    Coverage c;
    c.claimed = interval.level;
    if (!interval.known()) return c;
    std::size_t inside = 0;
    for (const RunData& run : runs) {
        const Prediction p = model.predict(run);
        if (!p.ok()) return c;
        const bool beyond = beyondTraining(training, run);
        for (std::size_t i = 0; i < run.observations.size(); ++i) {
            const ErrorObservation& o = run.observations[i];
            inside +=
                std::abs(o.error_um - p.error_um[i]) <= interval.halfWidthAt(o.position_mm, beyond);
            ++c.readings;
        }
    }
    if (c.readings > 0) c.share = double(inside) / double(c.readings);
    return c;
}

ValidatedFit fitValidated(const QString& name, const std::vector<RunData>& training,
                          const std::function<bool()>& cancelled) {
    if (!makeModel(name)) {
        ValidatedFit r;
        r.fit.message = QStringLiteral("'%1' is not a model").arg(name);
        return r;
    }
    return fitValidated([name] { return makeModel(name); }, training, cancelled);
}

ValidatedFit fitValidated(const ModelMaker& make, const std::vector<RunData>& training,
                          const std::function<bool()>& cancelled) {
    ValidatedFit r;
    r.model = make();
    if (cancelled) r.model->setCancelCheck(cancelled);
    r.fit = r.model->fit(training);
    if (!r.fit.success) return r;
    if (const auto* chooser = dynamic_cast<const AutoModel*>(r.model.get())) {
        r.validation = chooser->validation();
        try {
            nestBeyondInterval(training, &r.validation.interval, cancelled);
        } catch (const ModelError& e) {
            if (cancelled && cancelled()) {
                r.fit.success = false;
                r.fit.message = e.message;
                return r;
            }
            r.validation.interval.beyond_half_width_um = PredictionInterval::kNaN;
            r.validation.interval.beyond_by_position_um.clear();
            r.fit.notes
                << QStringLiteral("no interval beyond the training runs: %1").arg(e.message);
        }
    } else {
        try {
            r.validation =
                validationOf(crossValidatedPredictions(make, validationFolds(training), cancelled),
                             training.front().positionDependent(), training.size());
        } catch (const ModelError& e) {
            if (cancelled && cancelled()) {
                r.fit.success = false;
                r.fit.message = e.message;
                return r;
            }
            r.fit.notes << QStringLiteral("no cross-validation, so no prediction interval: %1")
                               .arg(e.message);
        }
    }
    r.fit.notes << validationNotes(r.validation);
    return r;
}

QStringList validationNotes(const Validation& v) {
    QStringList notes;
    if (!v.known()) return notes;
    if (v.interval.known())
        notes << QStringLiteral("prediction interval ±%1 µm%2: %3")
                     .arg(v.interval.half_width_um, 0, 'g', 3)
                     .arg(v.interval.position_mm.empty()
                              ? QString()
                              : QStringLiteral(" over all positions (%1 … %2 µm by position)")
                                    .arg(*std::min_element(
                                             v.interval.half_width_by_position_um.begin(),
                                             v.interval.half_width_by_position_um.end()),
                                         0, 'g', 3)
                                    .arg(*std::max_element(
                                             v.interval.half_width_by_position_um.begin(),
                                             v.interval.half_width_by_position_um.end()),
                                         0, 'g', 3))
                     .arg(v.interval.method);
    if (v.interval.knownBeyond())
        notes << QStringLiteral(
                     "beyond the training runs' temperature rises or spindle speeds the prediction "
                     "is an "
                     "extrapolation: there the interval is ±%1 µm, from the %2 readings of the "
                     "folds whose held-out part went beyond the runs they fitted on")
                     .arg(v.interval.beyond_half_width_um, 0, 'g', 3)
                     .arg(v.interval.beyond_readings);
    else if (v.interval.known())
        notes << QStringLiteral(
                     "%1: on a run beyond the training runs' temperature rises or spindle "
                     "speeds the interval is not known to hold")
                     .arg(v.interval.beyond_readings == 0
                              ? QStringLiteral("no fold of the training runs went beyond the "
                                               "runs it fitted on")
                              : QStringLiteral("the folds' extrapolations hold %1 readings, too "
                                               "few for an interval of their own")
                                    .arg(v.interval.beyond_readings));
    if (v.worseThanNone())
        notes << QStringLiteral(
                     "worse than no compensation where it was not fitted: %1. It would make "
                     "the machine worse; it is not pushed or exported without --force")
                     .arg(v.describe());
    return notes;
}

}  // namespace driftlab::models
