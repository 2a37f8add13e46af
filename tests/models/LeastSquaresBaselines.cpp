#include "tests/models/LeastSquaresBaselines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/models/AutoModel.h"
#include "core/models/LeastSquares.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::test {
namespace {

using namespace models;

/// Held-out RMS of least squares (with an offset) on the rises of `channels`.
double leastSquaresHeldOut(const std::vector<models::RunData>& train,
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
    return std::sqrt(r.squaredNorm() / double(r.size()));
}

}  // namespace

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
    b.all_rises_um = leastSquaresHeldOut(train, test, sensors, nullptr);
    // The pair a user would pick from the training runs: least training RSS.
    double bestPairRss = std::numeric_limits<double>::infinity();
    for (qsizetype i = 0; i < sensors.size(); ++i)
        for (qsizetype j = i + 1; j < sensors.size(); ++j) {
            double rss = 0;
            const double heldOut = leastSquaresHeldOut(train, test, {sensors[i], sensors[j]}, &rss);
            if (rss < bestPairRss) {
                bestPairRss = rss;
                b.best_pair_um = heldOut;
                b.best_pair = sensors[i] + QLatin1Char('+') + sensors[j];
            }
        }
    return b;
}

AutoAgainstBaselines autoAgainstBaselines(const std::vector<models::RunData>& train,
                                          const std::vector<models::RunData>& test,
                                          const QString& label) {
    AutoAgainstBaselines result;
    result.baselines = leastSquaresBaselines(train, test);
    models::AutoModel model;
    const models::FitSummary fit = model.fit(train);
    EXPECT_TRUE(fit.success) << qPrintable(label) << ": " << qPrintable(fit.message);
    if (!fit.success) return result;
    result.chosen = model.chosen();
    result.score = models::scoreModel(model, test);
    EXPECT_TRUE(result.score.ok()) << qPrintable(label) << ": " << qPrintable(result.score.error);
    std::printf("%-14s %6.3f µm (%-12s) %6.3f µm  %6.3f µm (%s)\n", qPrintable(label),
                result.score.rms_um, qPrintable(result.chosen), result.baselines.all_rises_um,
                result.baselines.best_pair_um, qPrintable(result.baselines.best_pair));
    return result;
}

void printAutoAgainstBaselinesHeader() {
    std::printf("held out       auto (chosen)          all rises  best pair (on training)\n");
}

}  // namespace driftlab::test
