#include "core/diagnosis/ExtendedHeatTransferModel.h"

#include <algorithm>

#include "core/diagnosis/CandidateEffects.h"
#include "core/models/ModelError.h"

namespace driftlab::diagnosis {
namespace {

const QString kBase = QStringLiteral("heat-transfer");

}  // namespace

ExtendedHeatTransferModel::ExtendedHeatTransferModel(QStringList causes)
    : m_causes(std::move(causes)) {}

QString ExtendedHeatTransferModel::name() const {
    return kBase + QLatin1Char('+') + m_causes.join(QLatin1Char('+'));
}

QStringList ExtendedHeatTransferModel::causesOf(const QString& model, QString* why) {
    QStringList parts = model.split(QLatin1Char('+'));
    if (parts.size() < 2 || parts.front() != kBase || parts.contains(QString())) {
        *why = QStringLiteral("'%1' is not an extension of heat-transfer (heat-transfer+CAUSE)")
                   .arg(model);
        return {};
    }
    parts.removeFirst();
    return parts;
}

models::FitSummary ExtendedHeatTransferModel::fitRuns(
    const std::vector<models::RunData>& training) {
    models::HeatTransferModel base(options());
    base.setCancelCheck([this] { return cancelRequested(); });
    const models::FitSummary baseFit = base.fit(training);
    if (!baseFit.success) throw models::ModelError(baseFit.message);
    std::vector<models::ReadingResiduals> residuals;
    for (const models::RunData& run : training) residuals.push_back(base.residuals(run));

    const std::vector<CandidateEffect> candidates = candidateEffects(training, residuals);
    std::vector<CandidateEffect> effects;
    for (const QString& cause : m_causes) {
        const auto found = std::find_if(candidates.begin(), candidates.end(),
                                        [&](const CandidateEffect& e) { return e.cause == cause; });
        if (found == candidates.end()) {
            QStringList online;
            for (const CandidateEffect& e : candidates)
                if (e.physics && !e.output_only) online << e.cause;
            throw models::ModelError(
                QStringLiteral("model '%1': the training runs cannot support %2; of the effects "
                               "that run online they support %3")
                    .arg(name(), cause, online.join(QStringLiteral(", "))));
        }
        // A sensor or interferometer effect changes what is read, not the
        // screw: a prediction of the screw has nothing of it to step.
        if (!found->physics || found->output_only)
            throw models::ModelError(
                QStringLiteral("model '%1': %2 changes what is read, not the screw's heat flow, "
                               "so it cannot run online; use heat-transfer")
                    .arg(name(), cause));
        effects.push_back(*found);
    }
    setVariant(extendedModel(effects, base.values()));
    models::FitSummary summary = HeatTransferModel::fitRuns(training);
    summary.notes << QStringLiteral("extended by %1, starting from the base fit's values")
                         .arg(m_causes.join(QStringLiteral(", ")));
    return summary;
}

}  // namespace driftlab::diagnosis
