#include "core/diagnosis/CandidateScoring.h"

#include <algorithm>
#include <cmath>

namespace driftlab::diagnosis {
namespace {

/// How far a room offset may pull a screw sensor from the soaked start:
/// calibration scatter between sensors that read the same soaked room (the
/// independent campaigns' sensors agree to 0.02 K).
constexpr double kSoakedStartTolerance_K = 0.03;

std::vector<models::ReadingResiduals> residualsOf(const models::HeatTransferModel& model,
                                                  const std::vector<models::RunData>& runs) {
    std::vector<models::ReadingResiduals> out;
    for (const auto& run : runs) out.push_back(model.residuals(run));
    return out;
}

double value(const Finding& f, std::size_t i) {
    return i < f.parameters.size() ? f.parameters[i].second.value : std::nan("");
}

/// Whether a fitted exponent differs from `assumed` by more than 2σ and 0.1.
bool differs(const models::Parameter& p, double assumed) {
    const double margin = std::isfinite(p.sigma) ? std::max(2 * p.sigma, 0.1) : 0.1;
    return std::abs(p.value - assumed) > margin;
}

QString effectWords(const Finding& f) {
    const QString base = f.cause.section(QLatin1Char(':'), 0, 0);
    const double v = value(f, 0);
    if (base == QLatin1String("forced_convection")) {
        if (f.parameters.size() < 2)
            return QStringLiteral(
                       "convection grows with screw speed: h rises by %1 W/(m²·K) at 800 rpm "
                       "(in proportion to speed: the training runs move at one speed, so the "
                       "speed law cannot be told)")
                .arg(v, 0, 'f', 1);
        const auto& m = f.parameters.at(1).second;
        return QStringLiteral(
                   "convection grows with screw speed: h rises by %1 W/(m²·K) at 800 rpm, "
                   "as speed^%2%3")
            .arg(v, 0, 'f', 1)
            .arg(m.value, 0, 'f', 2)
            .arg(differs(m, 1) ? QStringLiteral(" (not in proportion to speed: the speed law "
                                                "is not the one the base library assumed)")
                               : QString());
    }
    if (base == QLatin1String("nut_heat_exponent"))
        return QStringLiteral(
                   "nut friction power grows as speed^%1, not in proportion: at 1500 rpm the "
                   "nut makes %2× the heat a linear law predicts")
            .arg(v, 0, 'f', 2)
            .arg(std::pow(1500.0 / 800.0, v - 1), 0, 'f', 2);
    if (base == QLatin1String("motor_heat")) {
        // An entry length under a millimetre is heat into the end cell: say
        // where it enters rather than "over the first 0 mm".
        const double entry_mm = value(f, 2);
        return QStringLiteral("the servo motor heats the fixed end: %1 W per (N·m)² of torque, %2")
            .arg(v, 0, 'g', 3)
            .arg(entry_mm >= 1
                     ? QStringLiteral("entering over the first %1 mm").arg(entry_mm, 0, 'f', 0)
                     : QStringLiteral("entering at the fixed end"));
    }
    if (base == QLatin1String("sensor_lag") && f.effect.channel.isEmpty())
        return QStringLiteral(
                   "sensor %1 follows the %2 with a first-order lag of %3 s: the axis moved "
                   "with a %2 temperature the sensor showed only later")
            .arg(f.cause.section(QLatin1Char(':'), 1), f.effect.measures)
            .arg(v, 0, 'f', 0);
    if (base == QLatin1String("sensor_lag"))
        return QStringLiteral(
                   "sensor %1 follows the screw with a first-order lag of %2 s: it reads low "
                   "while the screw warms and high while it cools")
            .arg(f.effect.channel)
            .arg(v, 0, 'f', 0);
    if (base == QLatin1String("sensor_offset") && f.effect.channel.isEmpty())
        return QStringLiteral(
                   "room sensor %1 reads %2 K %3 throughout: the screw started at the true room "
                   "temperature, so against the model every screw sensor looks %2 K %4")
            .arg(f.cause.section(QLatin1Char(':'), 1))
            .arg(std::abs(v), 0, 'f', 2)
            .arg(v > 0 ? QStringLiteral("high") : QStringLiteral("low"))
            .arg(v > 0 ? QStringLiteral("low") : QStringLiteral("high"));
    if (base == QLatin1String("sensor_offset"))
        return QStringLiteral("sensor %1 reads %2 K %3 throughout")
            .arg(f.effect.channel)
            .arg(std::abs(v), 0, 'f', 2)
            .arg(v > 0 ? QStringLiteral("high") : QStringLiteral("low"));
    if (base == QLatin1String("air_refraction"))
        return QStringLiteral(
                   "the interferometer reading follows the air temperature over the beam "
                   "path (x + dead path): %1 of the Edlén correction (−0.95 ppm/K) is missing")
            .arg(v, 0, 'f', 2);
    if (base == QLatin1String("frame_growth"))
        return QStringLiteral(
                   "the axis zero moves with the structure temperature by %1 µm/K, the same "
                   "at every position, lagging the structure sensor by %2 min")
            .arg(v, 0, 'f', 2)
            .arg(value(f, 1) / 60, 0, 'f', 0);
    return f.cause;
}

}  // namespace

StepBase baseStep(std::shared_ptr<const models::HeatTransferModel> base,
                  const std::vector<models::RunData>& train,
                  const std::vector<models::RunData>& test) {
    StepBase b{{}, std::move(base), {}, {}, {}};
    b.train = residualsOf(*b.model, train);
    b.test = residualsOf(*b.model, test);
    b.test_summary = summarise(b.test, test);
    return b;
}

StepBase adoptedStepBase(std::vector<CandidateEffect> effects, const Finding& adopted) {
    return {std::move(effects), adopted.model, adopted.train_residuals, adopted.test_residuals,
            adopted.test_after};
}

namespace {

/// An effect that changes the heat flow, fitted on the screening grid from the
/// step's values and from the priors: the better of the two by its training
/// cost.
std::optional<FittedExtension> screenHeatFlowEffect(const StepBase& base,
                                                    const CandidateEffect& candidate,
                                                    const std::vector<double>& ownStart,
                                                    const StepData& data) {
    std::vector<CandidateEffect> effects = base.effects;
    effects.push_back(candidate);
    std::vector<double> fromStep = base.model->values();
    fromStep.insert(fromStep.end(), ownStart.begin(), ownStart.end());
    std::vector<double> fromPriors = base.model->values();
    const auto priors = models::baseScrewModel().parameters;
    for (std::size_t i = 0; i < priors.size(); ++i) fromPriors[i] = priors[i].initial;
    const models::HeatTransferOptions screening = screeningOptions(base.model->options());
    std::optional<FittedExtension> best;
    double bestCost = INFINITY;
    for (const std::vector<double>& start : {fromStep, fromPriors}) {
        auto coarse =
            std::make_shared<models::HeatTransferModel>(screening, extendedModel(effects, start));
        coarse->setCancelCheck(data.cancelled);
        models::FitSummary fit = coarse->fit(data.train);
        if (data.cancelled()) return std::nullopt;
        if (!fit.success || !(fit.metrics.at(QStringLiteral("final_cost")) < bestCost)) continue;
        bestCost = fit.metrics.at(QStringLiteral("final_cost"));
        fit.notes << QStringLiteral("screened on a %1-cell grid in %2 s steps")
                         .arg(kScreeningCells)
                         .arg(kScreeningStep_s);
        best = FittedExtension{coarse, std::move(fit)};
    }
    return best;
}

/// `screened` fitted again on the grid of `options`, from its screening values.
std::optional<FittedExtension> refined(const FittedExtension& screened,
                                       const models::HeatTransferOptions& options,
                                       const StepData& data) {
    models::ScrewModelVariant variant = screened.model->variant();
    for (std::size_t i = 0; i < variant.parameters.size(); ++i)
        variant.parameters[i].initial = screened.model->values()[i];
    auto model = std::make_shared<models::HeatTransferModel>(options, std::move(variant));
    model->setCancelCheck(data.cancelled);
    FittedExtension fitted{model, model->fit(data.train)};
    if (!fitted.fit.success || data.cancelled()) return std::nullopt;
    return fitted;
}

/// The finding of `candidate` fitted as `fitted` on top of `base`: its gain on
/// the held-out runs on the quantity it shows in, BIC, whether it is a fit
/// compromise, its significance and evidence.
Finding judged(const StepBase& base, const CandidateEffect& candidate,
               const FittedExtension& fitted, int step, const StepData& data) {
    Finding f;
    f.cause = candidate.cause;
    f.step = step;
    f.effect = candidate;
    f.fit = fitted.fit;
    for (const auto& p : candidate.parameters)
        f.parameters.emplace_back(p.name, f.fit.parameters.at(p.name));
    f.model = fitted.model;
    const auto& model = fitted.model;

    f.train_residuals = residualsOf(*model, data.train);
    f.test_residuals = residualsOf(*model, data.test);
    const auto& train = f.train_residuals;
    const auto& test = f.test_residuals;
    f.test_before = base.test_summary;
    f.test_after = summarise(test, data.test);
    const QString& channel = candidate.channel;
    f.gain.quantity = channel.isEmpty() ? QStringLiteral("positioning")
                                        : QStringLiteral("temperature:") + channel;
    f.gain.unit = channel.isEmpty() ? QStringLiteral("µm") : QStringLiteral("K");
    f.gain.test_rms_before = quantityResidual(base.test, channel).rms();
    f.gain.test_rms_after = quantityResidual(test, channel).rms();
    f.gain.reduction =
        f.gain.test_rms_before > 0 ? 1 - f.gain.test_rms_after / f.gain.test_rms_before : 0;
    f.gain.stretches = stretchSquares(base.test, test, channel);
    // BIC with the noise variance estimated, on the gain's quantity:
    // N·ln(S₀/S₁) − k·ln N for the k parameters the effect adds.
    const QuantityResidual before = quantityResidual(base.train, channel);
    const QuantityResidual after = quantityResidual(train, channel);
    const double n = double(after.count);
    f.bic_drop = after.sum_squares > 0 && before.sum_squares > 0
                     ? n * std::log(before.sum_squares / after.sum_squares) -
                           double(candidate.parameters.size()) * std::log(n)
                     : 0;
    // A sensor effect that buys its gain on one sensor by making the
    // positioning error worse is a fit compromise, not a cause; so is an
    // effect on the axis that buys its positioning gain by making the screw
    // temperatures worse: the heat balance bent to fit the error. A true
    // effect's extension fits both readings at once (named causes on the rig
    // and the independent campaigns: at most 6 % worse, docs/diagnosis.md §4).
    f.fit_compromise =
        !(channel.isEmpty()
              ? f.test_after.temperature_rms_K <= 1.2 * f.test_before.temperature_rms_K + 0.01
              : f.test_after.error_rms_um <= 1.02 * f.test_before.error_rms_um + 0.02);
    // A room sensor's offset moves every screw sensor against the model. At
    // the soaked start of a run, before any heat acts, each screw sensor reads
    // the room the screw soaked in: a true offset brings all of them to the
    // model there. One that pulls a sensor away from it is spreading another
    // sensor's offset, or a heat input, over all of them (the independent
    // campaigns' nut-sensor offset under motor heat, docs/diagnosis.md §4).
    QString pulledAway;
    if (channel.isEmpty() && candidate.cause.startsWith(QLatin1String("sensor_offset:")) &&
        !base.test.empty())
        for (const auto& sensor : base.test.front().sensors) {
            const double from = soakedStartResidual_K(base.test, sensor.channel_id);
            const double to = soakedStartResidual_K(test, sensor.channel_id);
            if (to > from + kSoakedStartTolerance_K && pulledAway.isEmpty()) {
                f.fit_compromise = true;
                pulledAway = QStringLiteral(
                                 ": it pulls sensor %1 away from the room temperature the "
                                 "screw soaked in (at the held-out runs' start %2 → %3 K "
                                 "RMS), a fit compromise, not a cause")
                                 .arg(sensor.channel_id)
                                 .arg(from, 0, 'f', 3)
                                 .arg(to, 0, 'f', 3);
            }
        }
    // Nor is an effect on a sensor that changes its reading by less than the
    // sensor's noise (with thousands of readings BIC finds that significant):
    // the part of the held-out residual it removes, √(before² − after²), must
    // stand above the noise.
    const double noise_K = channel.isEmpty() ? NAN : residualNoise_K(base.test, channel);
    const double removed = std::sqrt(
        std::max(0.0, std::pow(f.gain.test_rms_before, 2) - std::pow(f.gain.test_rms_after, 2)));
    const bool aboveNoise = !(noise_K > 0) || removed > noise_K;
    f.significant = !f.fit_compromise && aboveNoise && f.bic_drop > data.options.min_bic_drop &&
                    f.gain.reduction > data.options.min_test_gain;
    f.evidence = evidenceFor(f, data.test_ids);
    if (!pulledAway.isEmpty())
        f.evidence += pulledAway;
    else if (f.fit_compromise)
        f.evidence += channel.isEmpty() ? QStringLiteral(
                                              ": it bends the heat balance to fit the positioning "
                                              "error, a fit compromise, not a cause")
                                        : QStringLiteral(
                                              ": it makes the positioning error worse, a fit "
                                              "compromise, not a cause");
    return f;
}

}  // namespace

models::HeatTransferOptions screeningOptions(const models::HeatTransferOptions& options) {
    models::HeatTransferOptions screening = options;
    screening.cells = kScreeningCells;
    screening.dt_s = kScreeningStep_s;
    return screening;
}

std::optional<StepBase> screeningStep(const StepBase& base,
                                      const std::vector<models::RunData>& train,
                                      const std::vector<models::RunData>& test,
                                      const std::function<bool()>& cancelled) {
    models::ScrewModelVariant variant = base.model->variant();
    for (std::size_t i = 0; i < variant.parameters.size(); ++i)
        variant.parameters[i].initial = base.model->values()[i];
    auto model = std::make_shared<models::HeatTransferModel>(
        screeningOptions(base.model->options()), std::move(variant));
    model->setCancelCheck(cancelled);
    if (!model->fit(train).success) return std::nullopt;
    StepBase coarse = baseStep(model, train, test);
    coarse.effects = base.effects;
    return coarse;
}

std::optional<Finding> scoreCandidate(const StepBase& base, const CandidateEffect& candidate,
                                      const std::vector<double>& ownStart, int step,
                                      const StepData& data) {
    if (candidate.output_only && data.simulation) {
        const auto fitted = data.simulation->fit(candidate, ownStart, data.cancelled);
        if (!fitted || data.cancelled()) return std::nullopt;
        return judged(base, candidate, *fitted, step, data);
    }
    const auto screened = screenHeatFlowEffect(base, candidate, ownStart, data);
    if (!screened || data.cancelled()) return std::nullopt;
    // Judged on the screening grid against the step's model on that grid;
    // refined on the step's own grid only where the gain there is one the
    // candidate could be named for.
    if (data.screening) {
        Finding coarse = judged(*data.screening, candidate, *screened, step, data);
        if (!(coarse.gain.reduction > kRefineAbove * data.options.min_test_gain)) {
            coarse.significant = false;
            return coarse;
        }
    }
    models::HeatTransferOptions refining = base.model->options();
    refining.max_iterations = kRefineIterations;
    const auto fitted = refined(*screened, refining, data);
    if (!fitted || data.cancelled()) return std::nullopt;
    return judged(base, candidate, *fitted, step, data);
}

QString evidenceFor(const Finding& f, const QStringList& testRuns) {
    const bool onPositioning = f.gain.quantity == QLatin1String("positioning");
    const QString quantity =
        onPositioning
            ? QStringLiteral("positioning residual")
            : QStringLiteral("residual of %1").arg(f.gain.quantity.section(QLatin1Char(':'), 1));
    const int digits = f.gain.unit == QLatin1String("K") ? 3 : 2;
    // The gain's own quantity first; then the other quantities, not the same again.
    const QString positioning =
        onPositioning ? QString()
                      : QStringLiteral("the positioning residual from %1 to %2 µm RMS and ")
                            .arg(f.test_before.error_rms_um, 0, 'f', 2)
                            .arg(f.test_after.error_rms_um, 0, 'f', 2);
    return effectWords(f) +
           QStringLiteral(
               "; on held-out runs %1 the %2 goes from %3 to %4 %5 RMS (%6 % less); %7"
               "the screw-temperature residual from %8 to %9 K RMS")
               .arg(testRuns.join(QStringLiteral(", ")), quantity)
               .arg(f.gain.test_rms_before, 0, 'f', digits)
               .arg(f.gain.test_rms_after, 0, 'f', digits)
               .arg(f.gain.unit)
               .arg(100 * f.gain.reduction, 0, 'f', 0)
               .arg(positioning)
               .arg(f.test_before.temperature_rms_K, 0, 'f', 3)
               .arg(f.test_after.temperature_rms_K, 0, 'f', 3);
}

}  // namespace driftlab::diagnosis
