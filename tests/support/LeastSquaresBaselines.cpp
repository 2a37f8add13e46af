#include "tests/support/LeastSquaresBaselines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/domain/Median.h"
#include "core/models/AutoModel.h"
#include "core/models/LeastSquares.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::test {
namespace {

using namespace models;

/// The measured drift and the residual of a model, summed in stretches of
/// the held-out runs' time as the diagnosis sums its residuals.
diagnosis::StretchSquares heldOutStretches(const std::vector<RunData>& test,
                                           const Eigen::VectorXd& residual_um) {
    constexpr int perRun = diagnosis::kStretchesPerRun;
    diagnosis::StretchSquares s;
    s.before.assign(test.size() * perRun, 0.0);
    s.after.assign(test.size() * perRun, 0.0);
    Eigen::Index at = 0;
    for (std::size_t r = 0; r < test.size(); ++r) {
        const Eigen::VectorXd measured = test[r].observedErrors();
        const auto& obs = test[r].observations;
        for (Eigen::Index i = 0; i < measured.size(); ++i, ++at) {
            const int k = diagnosis::stretchOf(obs[std::size_t(i)].time_s, obs.front().time_s,
                                               obs.back().time_s, perRun);
            s.before[r * perRun + k] += measured[i] * measured[i];
            s.after[r * perRun + k] += residual_um[at] * residual_um[at];
        }
    }
    return s;
}

/// Held-out RMS of least squares (with an offset) on the rises of `channels`.
HeldOut leastSquaresHeldOut(const std::vector<models::RunData>& train,
                            const std::vector<models::RunData>& test, const QStringList& channels,
                            double* trainRss) {
    auto design = [&](const RunData& run) {
        const Eigen::MatrixXd rises = risesAt(run, channels, run.observationPoints());
        Eigen::MatrixXd X(rises.rows(), rises.cols() + 1);
        X << rises, Eigen::VectorXd::Ones(rises.rows());
        return X;
    };
    const LeastSquaresFit fit =
        solveLeastSquares(stackRows(train, design), stackRows(train, &RunData::observedErrors));
    if (trainRss) *trainRss = fit.rss;
    const Eigen::VectorXd r =
        stackRows(test, &RunData::observedErrors) - stackRows(test, design) * fit.coefficients;
    return {std::sqrt(r.squaredNorm() / double(r.size())), heldOutStretches(test, r)};
}

}  // namespace

HeldOut perfectModelHeldOut(const std::vector<models::RunData>& test,
                            const std::vector<std::vector<double>>& truth_um,
                            double referenceWindow_s) {
    Eigen::VectorXd residual(stackRows(test, &RunData::observedErrors));
    Eigen::Index at = 0;
    for (std::size_t r = 0; r < test.size(); ++r) {
        const auto& obs = test[r].observations;
        const std::vector<double>& truth = truth_um[r];
        EXPECT_EQ(truth.size(), obs.size()) << qPrintable(test[r].run_id);
        std::vector<double> window;
        for (std::size_t i = 0; i < obs.size() && i < truth.size(); ++i)
            if (obs[i].time_s <= obs.front().time_s + referenceWindow_s) window.push_back(truth[i]);
        const double zero_um = window.empty() ? 0 : median(window);
        for (std::size_t i = 0; i < obs.size(); ++i, ++at)
            residual[at] -= i < truth.size() ? truth[i] - zero_um : 0;
    }
    return {std::sqrt(residual.squaredNorm() / double(residual.size())),
            heldOutStretches(test, residual)};
}

std::vector<models::RunData> driftDataset(const Campaign& c, const QStringList& runs,
                                          const QString& target) {
    models::DatasetOptions options;
    options.target_channel = target;
    const models::DatasetResult data = models::buildDataset(c, runs, options);
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

LeastSquaresBaselines leastSquaresBaselines(const std::vector<models::RunData>& train,
                                            const std::vector<models::RunData>& test) {
    QStringList sensors;
    for (const TemperatureRise& t : train.front().temperatures)
        if (t.unusable.isEmpty()) sensors << t.channel_id;
    LeastSquaresBaselines b;
    b.all_rises = leastSquaresHeldOut(train, test, sensors, nullptr);
    // The pair a user would pick from the training runs: least training RSS.
    double bestPairRss = std::numeric_limits<double>::infinity();
    for (qsizetype i = 0; i < sensors.size(); ++i)
        for (qsizetype j = i + 1; j < sensors.size(); ++j) {
            double rss = 0;
            HeldOut heldOut = leastSquaresHeldOut(train, test, {sensors[i], sensors[j]}, &rss);
            if (rss < bestPairRss) {
                bestPairRss = rss;
                b.best_pair = std::move(heldOut);
                b.best_pair_sensors = sensors[i] + QLatin1Char('+') + sensors[j];
            }
        }
    return b;
}

AutoAgainstBaselines autoAgainstBaselines(const std::vector<models::RunData>& train,
                                          const std::vector<models::RunData>& test,
                                          const QString& label, HeldOut perfect) {
    AutoAgainstBaselines result;
    result.baselines = leastSquaresBaselines(train, test);
    models::AutoModel model;
    const models::FitSummary fit = model.fit(train);
    EXPECT_TRUE(fit.success) << qPrintable(label) << ": " << qPrintable(fit.message);
    if (!fit.success) return result;
    result.chosen = model.chosen();
    result.weights = model.weights();
    result.coverage = models::coverageOf(model, model.validation().interval, test, train);
    // Predicted once: scored, and summed by stretch for the comparison.
    const Eigen::VectorXd measured = stackRows(test, &RunData::observedErrors);
    Eigen::VectorXd predicted(measured.size());
    Eigen::Index at = 0;
    for (const RunData& run : test) {
        const Prediction p = model.predict(run);
        EXPECT_TRUE(p.ok()) << qPrintable(label) << ": " << qPrintable(p.error);
        if (!p.ok()) return result;
        for (double value : p.error_um) predicted[at++] = value;
    }
    result.score = models::scoreResiduals(measured, predicted);
    const diagnosis::StretchSquares autoStretches = heldOutStretches(test, measured - predicted);
    const LeastSquaresBaselines& b = result.baselines;
    result.probability_better =
        std::min(diagnosis::probabilityLarger(autoStretches, &b.all_rises.stretches),
                 diagnosis::probabilityLarger(autoStretches, &b.best_pair.stretches));
    result.probability_perfect_better =
        std::min(diagnosis::probabilityLarger(perfect.stretches, &b.all_rises.stretches),
                 diagnosis::probabilityLarger(perfect.stretches, &b.best_pair.stretches));
    result.perfect = std::move(perfect);
    return result;
}

QString AutoAgainstBaselines::text() const {
    return QStringLiteral(
               "auto %1 µm (%2), every rise %3 µm, best pair %4 µm (%5), a perfect model %6 µm; "
               "P(auto better than both) %7")
        .arg(score.rms_um, 0, 'f', 3)
        .arg(chosen)
        .arg(baselines.all_rises.rms_um, 0, 'f', 3)
        .arg(baselines.best_pair.rms_um, 0, 'f', 3)
        .arg(baselines.best_pair_sensors)
        .arg(perfect.rms_um, 0, 'f', 3)
        .arg(probability_better, 0, 'f', 3);
}

void AutoAgainstBaselinesTally::add(const AutoAgainstBaselines& a) {
    ++cases;
    beaten += a.beatsBoth();
    surely_better += a.probability_better > 0.95;
    surely_worse += a.probability_better < 0.05;
    perfect_beats += a.perfectSurelyBeatsBoth();
    beaten_where_perfect_beats += a.perfectSurelyBeatsBoth() && a.beatsBoth();
    tied += a.tiesTheBetter();
    tied_where_perfect_beats += a.perfectSurelyBeatsBoth() && a.tiesTheBetter();
}

QString AutoAgainstBaselinesTally::text() const {
    return QStringLiteral(
               "auto beats both baselines on %1 of %2 (and ties the better within 0.001 µm on "
               "%3); surely (P > 0.95) on %4; a baseline surely better on %5; a perfect model "
               "beats both beyond chance on %6, auto beats both on %7 of those (and ties on %8)")
        .arg(beaten)
        .arg(cases)
        .arg(tied)
        .arg(surely_better)
        .arg(surely_worse)
        .arg(perfect_beats)
        .arg(beaten_where_perfect_beats)
        .arg(tied_where_perfect_beats);
}

}  // namespace driftlab::test
