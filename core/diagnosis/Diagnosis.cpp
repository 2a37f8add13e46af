#include "core/diagnosis/Diagnosis.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>

#include "core/diagnosis/CandidateScoring.h"
#include "core/diagnosis/CauseSelection.h"
#include "core/models/ModelError.h"

namespace driftlab::diagnosis {
namespace {

/// Whether an extension explains the whole discrepancy: the positioning
/// residual it leaves is within `factor` × the reading noise, and the worst
/// temperature residual within that of the sensor noise or a tenth of what the
/// base model left (a heat input estimated from a 10 s torque log cannot be
/// exact; a tenth left over is a cause found, not a different cause).
bool leavesOnlyNoise(const ResidualSummary& after, const ResidualSummary& before, double factor) {
    const bool positioning =
        !(after.error_noise_um > 0) || after.error_rms_um <= factor * after.error_noise_um;
    const double temperatureAllowed =
        std::max(factor * after.worst_channel_noise_K + 0.01, 0.1 * before.worst_channel_rms_K);
    return positioning && after.worst_channel_rms_K <= temperatureAllowed;
}

struct Cancelled {};

/// Every candidate on top of `base`, ranked; throws Cancelled. The fits are
/// independent: two at a time (the reference machine has two cores).
std::vector<Finding> testCandidates(
    const StepBase& base,
    const std::vector<std::pair<CandidateEffect, std::vector<double>>>& candidates, int step,
    const StepData& data, std::atomic<double>* done, double from, double to) {
    // The step's simulation, shared by the effects on the readings, and its
    // model on the screening grid, for the effects on the heat flow.
    const StepSimulation simulation(base.model, base.effects, data.train);
    const std::optional<StepBase> screening =
        screeningStep(base, data.train, data.test, data.cancelled);
    if (data.cancelled()) throw Cancelled{};
    StepData withSimulation = data;
    withSimulation.simulation = &simulation;
    withSimulation.screening = screening ? &*screening : nullptr;
    std::vector<std::optional<Finding>> scored(candidates.size());
    std::vector<std::exception_ptr> failed(candidates.size());
    // The longest fits first, so that the two workers end together: the
    // effects on the heat flow (new simulations), those with the most free
    // parameters first; the effects on the readings, a few hundredths of a
    // second each, fill in at the end.
    std::vector<std::size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto cost = [&](std::size_t k) {
        const CandidateEffect& c = candidates[k].first;
        return c.output_only ? 0 : 1 + c.parameters.size();
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i; (i = next++) < candidates.size();) {
            const std::size_t k = order[i];
            *done = from + (to - from) * double(i) / double(candidates.size());
            if (data.cancelled()) return;
            try {
                scored[k] = scoreCandidate(base, candidates[k].first, candidates[k].second, step,
                                           withSimulation);
            } catch (...) {
                failed[k] = std::current_exception();
            }
        }
    };
    const unsigned workers = std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
    std::vector<std::thread> threads;
    for (unsigned w = 1; w < workers; ++w) threads.emplace_back(work);
    work();
    for (auto& t : threads) t.join();
    if (data.cancelled()) throw Cancelled{};
    for (const auto& e : failed)
        if (e) std::rethrow_exception(e);
    std::vector<Finding> findings;
    for (auto& f : scored)
        if (f) findings.push_back(std::move(*f));  // none: an extension the data cannot carry
    rankFindings(findings, base.test);
    admitHeldOutEvidence(findings, data.options);
    return findings;
}

QString percent(double share) {
    return QString::number(100 * share, 'f', 0) + QStringLiteral(" %");
}

}  // namespace

const Finding* adoptedFinding(const DiagnosisResult& r, const QString& cause) {
    const int step = int(r.causes.indexOf(cause)) + 1;
    for (const auto& f : r.findings)
        if (step > 0 && f.cause == cause && f.step == step) return &f;
    return nullptr;
}

const Finding* verdictFinding(const DiagnosisResult& r) {
    return r.causes.isEmpty() ? nullptr : adoptedFinding(r, r.causes.back());
}

const models::ReadingResiduals* adoptedResiduals(const DiagnosisResult& r, std::size_t k) {
    const Finding* f = verdictFinding(r);
    return f && k < f->test_residuals.size() ? &f->test_residuals[k] : nullptr;
}

QString parametersText(const Finding& f) {
    QStringList parts;
    for (const auto& [name, p] : f.parameters)
        parts << QStringLiteral("%1 = %2 ± %3 %4")
                     .arg(name)
                     .arg(p.value, 0, 'g', 4)
                     .arg(std::isfinite(p.sigma) ? QString::number(p.sigma, 'g', 2)
                                                 : QStringLiteral("?"))
                     .arg(p.unit)
                     .trimmed();
    return parts.join(QStringLiteral(", "));
}

void splitRuns(const Campaign& campaign, QStringList* train, QStringList* test) {
    QStringList runs;
    for (const Run& r : campaign.runs)
        if (isFeedAxisRun(r.kind) && !r.positioning.empty()) runs << r.id;
    const qsizetype testCount =
        runs.size() < 2 ? 0 : std::max<qsizetype>(1, (runs.size() * 2 + 2) / 5);
    *train = runs.mid(0, runs.size() - testCount);
    *test = runs.mid(runs.size() - testCount);
}

DiagnosisResult diagnose(const Campaign& campaign, const DiagnosisOptions& options) {
    DiagnosisResult result;
    result.train_runs = options.train_runs;
    result.test_runs = options.test_runs;
    if (result.train_runs.isEmpty() && result.test_runs.isEmpty())
        splitRuns(campaign, &result.train_runs, &result.test_runs);
    for (const QString& id : result.test_runs)
        if (result.train_runs.contains(id)) {
            result.error = QStringLiteral("run '%1' is both a training and a test run").arg(id);
            return result;
        }
    if (result.train_runs.isEmpty() || result.test_runs.isEmpty()) {
        result.error = QStringLiteral(
                           "the diagnosis needs training and held-out runs: this "
                           "campaign has %1 feed-axis run(s) with positioning data")
                           .arg(result.train_runs.size() + result.test_runs.size());
        return result;
    }
    const models::DatasetResult train = models::buildDataset(campaign, result.train_runs);
    const models::DatasetResult test = models::buildDataset(campaign, result.test_runs);
    if (!train.ok() || !test.ok()) {
        result.error = train.ok() ? test.error : train.error;
        return result;
    }
    result.gaps = models::gapsOf(train.runs);
    for (const models::DataGap& g : models::gapsOf(test.runs)) result.gaps.push_back(g);

    // Asked between candidates and, through the models' cancel check, inside
    // each fit, from both fitting threads: the caller's callback is called by
    // one at a time.
    std::atomic<double> done{0};
    std::atomic<bool> stopped{false};
    std::mutex progressMutex;
    const auto cancelled = [&] {
        if (stopped || !options.progress) return bool(stopped);
        const std::lock_guard lock(progressMutex);
        if (!options.progress(done)) stopped = true;
        return bool(stopped);
    };
    // Gains are read to a per cent: the identification need not go on to
    // round-off, and the diagnosis makes some twenty fits.
    models::HeatTransferOptions fitting;
    fitting.function_tolerance = 1e-6;
    fitting.parameter_tolerance = 1e-5;
    auto base = std::make_shared<models::HeatTransferModel>(fitting);
    base->setCancelCheck(cancelled);
    result.base_fit = base->fit(train.runs);
    if (stopped) {
        result.error = QStringLiteral("diagnosis cancelled");
        return result;
    }
    if (!result.base_fit.success) {
        result.error = result.base_fit.message;
        return result;
    }
    try {
        const StepData data{train.runs, test.runs, result.test_runs, options, cancelled};
        const StepBase step1 = baseStep(base, train.runs, test.runs);
        result.base_residuals = step1.test;
        result.base_test = step1.test_summary;

        std::vector<std::pair<CandidateEffect, std::vector<double>>> candidates;
        std::vector<CandidateEffect> onTopOfOthers;
        for (auto& c : candidateEffects(train.runs, step1.train)) {
            if (c.on_top_of.isEmpty())
                candidates.push_back({c, {}});
            else
                onTopOfOthers.push_back(c);
        }
        result.findings = testCandidates(step1, candidates, 1, data, &done, 0, 0.7);
        // Nothing is named on a base model that already fits to the noise,
        // unless the held-out stretches show beyond doubt that part of it is
        // a candidate's effect: a noise estimate is a summary, the stretches
        // test each candidate's gain directly.
        const Finding* first = bestSignificant(result.findings, step1.test);
        if (first && result.base_test.atNoiseLevel() &&
            first->confidence < options.min_confidence_at_noise)
            first = nullptr;
        QStringList causes;
        std::optional<StepBase> adopted;
        if (first) {
            causes << first->cause;
            adopted = adoptedStepBase({first->effect}, *first);
            // Step 2: what else helped on the held-out runs in step 1 (another
            // effect may show only once the first is accounted for), tested
            // again on what the cause leaves, from its own step-1 values;
            // unless the cause leaves only noise by the noise-level test (the
            // verdict's 2× would end the search above a second effect).
            if (!leavesOnlyNoise(adopted->test_summary, result.base_test, kNoiseLevelTolerance)) {
                // The lags of sensors the cause reads first: their fits are the
                // longest, and the other worker takes the rest meanwhile.
                std::vector<std::pair<CandidateEffect, std::vector<double>>> rest;
                for (const auto& c : onTopOfOthers)
                    if (c.on_top_of == first->cause) rest.push_back({c, {}});
                for (const auto& f : result.findings) {
                    // An effect that the training runs show may be masked on the
                    // held-out runs by the first cause's larger error: on the
                    // axis, or on a sensor the bent fit pulled toward its
                    // reading (a nut sensor's offset under motor heat).
                    const bool showsOnTraining = f.bic_drop > options.min_bic_drop;
                    // An effect on the heat flow is tried again whatever its
                    // step-1 figures: its fit bends to follow the first cause
                    // (motor heat spreading over the screw to explain a nut
                    // sensor's offset) and scores against it.
                    const bool onHeatFlow = !f.effect.output_only;
                    if (!(f.gain.reduction > 0 || showsOnTraining || onHeatFlow) ||
                        f.cause == first->cause)
                        continue;
                    std::vector<double> own;
                    for (const auto& p : f.parameters) own.push_back(p.second.value);
                    rest.push_back({f.effect, own});
                }
                const auto second = testCandidates(*adopted, rest, 2, data, &done, 0.7, 1);
                const Finding* next = secondCause(second, *first, adopted->test, options);
                if (next) {
                    causes << next->cause;
                    adopted = adoptedStepBase({first->effect, next->effect}, *next);
                }
                result.findings.insert(result.findings.end(), second.begin(), second.end());
                for (const auto& f : result.findings)  // the insert moved it
                    if (f.cause == causes.front() && f.step == 1) first = &f;
            }
        }
        // Named when the causes explain most of the discrepancy, or all of it
        // but noise; part of it is not a cause found. On positioning "most"
        // is read on the structure's RMS, the noise taken out of before and
        // after: 1 − after/before, which keeps the noise in both, is never
        // above it where there is positioning structure.
        const double explained =
            adopted ? std::max(first->gain.reduction,
                               structureRmsExplained(result.base_test, adopted->test_summary))
                    : 0;
        const bool named = adopted && (explained >= options.min_explained ||
                                       leavesOnlyNoise(adopted->test_summary, result.base_test,
                                                       options.max_residual_over_noise));
        if (named) {
            const double positioningExplained =
                1 -
                adopted->test_summary.error_rms_um / std::max(result.base_test.error_rms_um, 1e-12);
            result.verdict = causes.front();
            result.causes = causes;
            // What the causes leave above the noise is a cause outside the
            // library, and a named one may be imitating it: the probability
            // that its gain is real and the largest is not yet that it is the
            // cause. Its confidence keeps the share of the structure explained.
            result.structure_explained =
                structureExplained(result.base_test, adopted->test_summary);
            for (auto& f : result.findings)
                if (f.step == causes.indexOf(f.cause) + 1)
                    f.confidence *= result.structure_explained;
            if (!adopted->test_summary.atNoiseLevel())
                result.remaining =
                    QStringLiteral(
                        "%1 explain%2 %3 of the positioning residual (%4 → %5 µm RMS), %6 "
                        "of its structure above the noise; the rest, against %7 µm reading "
                        "noise: %8")
                        .arg(result.causes.join(QStringLiteral(" and ")),
                             result.causes.size() > 1 ? QString() : QStringLiteral("s"),
                             percent(positioningExplained))
                        .arg(result.base_test.error_rms_um, 0, 'f', 2)
                        .arg(adopted->test_summary.error_rms_um, 0, 'f', 2)
                        .arg(percent(result.structure_explained))
                        .arg(adopted->test_summary.error_noise_um, 0, 'f', 2)
                        .arg(describeStructure(adopted->test, test.runs));
        } else if (result.base_test.atNoiseLevel()) {
            result.verdict = QStringLiteral("none");
            result.verdict_evidence =
                QStringLiteral(
                    "the base model fits to the noise: positioning residual %1 µm RMS "
                    "(reading noise %2 µm), worst temperature residual %3 K RMS on %4 "
                    "(sensor noise %5 K)")
                    .arg(result.base_test.error_rms_um, 0, 'f', 2)
                    .arg(result.base_test.error_noise_um, 0, 'f', 2)
                    .arg(result.base_test.worst_channel_rms_K, 0, 'f', 3)
                    .arg(result.base_test.worst_channel)
                    .arg(result.base_test.worst_channel_noise_K, 0, 'f', 3);
        } else {
            result.verdict = QStringLiteral("unexplained");
            result.verdict_evidence =
                QStringLiteral(
                    "structure remains that no candidate explains: %1; positioning "
                    "residual %2 µm RMS against %3 µm reading noise; worst temperature "
                    "residual %4 K RMS on %5 against %6 K sensor noise")
                    .arg(describeStructure(result.base_residuals, test.runs))
                    .arg(result.base_test.error_rms_um, 0, 'f', 2)
                    .arg(result.base_test.error_noise_um, 0, 'f', 2)
                    .arg(result.base_test.worst_channel_rms_K, 0, 'f', 3)
                    .arg(result.base_test.worst_channel)
                    .arg(result.base_test.worst_channel_noise_K, 0, 'f', 3);
            if (adopted)
                result.verdict_evidence +=
                    QStringLiteral(
                        "; %1 would remove %2 of it but leave %3 µm RMS and %4 K RMS on %5 "
                        "(noise %6 K): they explain part of it, not most")
                        .arg(causes.join(QStringLiteral(" and ")), percent(explained))
                        .arg(adopted->test_summary.error_rms_um, 0, 'f', 2)
                        .arg(adopted->test_summary.worst_channel_rms_K, 0, 'f', 3)
                        .arg(adopted->test_summary.worst_channel)
                        .arg(adopted->test_summary.worst_channel_noise_K, 0, 'f', 3);
        }
    } catch (const Cancelled&) {
        result.error = QStringLiteral("diagnosis cancelled");
        return result;
    } catch (const models::ModelError& e) {
        result.error = e.message;
    }
    if (options.progress) options.progress(1.0);
    return result;
}

}  // namespace driftlab::diagnosis
