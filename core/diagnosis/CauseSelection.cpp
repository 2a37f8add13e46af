#include "core/diagnosis/CauseSelection.h"

#include <algorithm>
#include <cmath>

#include "core/diagnosis/StretchJackknife.h"

namespace driftlab::diagnosis {
namespace {

/// Whether a significant effect on the axis also explains most of what the
/// sensor effect `s` explains on its sensor: one physical cause that fits
/// every reading beats an effect on one sensor that absorbs its share of the
/// base model's compromise.
bool explainedByPhysics(const Finding& s, const std::vector<Finding>& findings,
                        const std::vector<models::ReadingResiduals>& before) {
    const double base = quantityResidual(before, s.effect.channel).rms();
    for (const auto& p : findings) {
        if (!p.significant || !p.effect.channel.isEmpty() || !(base > 0)) continue;
        const double reduction =
            1 - quantityResidual(p.test_residuals, s.effect.channel).rms() / base;
        if (reduction >= 0.8 * s.gain.reduction) return true;
    }
    return false;
}

/// Whether a sensor effect explains most of its sensor's residual, as a
/// first cause must explain most of its quantity's: the share of the
/// residual's RMS it removes, or of its structure's RMS with the residual's
/// noise taken out of before and after. A fault of one sensor leaves that
/// sensor at its noise. A lag taking a fifth of a bearing sensor's residual
/// was fitting the model's form there: bearing heat spread over a seat around
/// the sensor, where the model puts it into the end cell (docs/diagnosis.md §4).
bool explainsMostOfItsSensor(const Finding& f, const std::vector<models::ReadingResiduals>& base,
                             double minExplained) {
    if (f.gain.reduction >= minExplained) return true;
    const double noise_K = residualNoise_K(base, f.effect.channel);
    if (!(f.gain.test_rms_before > noise_K)) return false;  // also NaN: no noise to take out
    const double share =
        shareAboveNoiseExplained(f.gain.test_rms_before, f.gain.test_rms_after, noise_K);
    return 1 - std::sqrt(1 - share) >= minExplained;
}

}  // namespace

/// Best held-out gain first. The confidence of each: the probability that
/// its gain is real and larger than every other candidate's, on the held-out
/// stretches (StretchJackknife). The chances of these failing are summed, so
/// the confidence is a lower bound (Bonferroni) and needs no assumption on
/// how the candidates' gains correlate. A fit compromise is no competitor;
/// nor is a sensor effect the physics explains on its sensor, and it is not a
/// cause of its own (confidence 0): it is the same cause seen on one sensor.
void rankFindings(std::vector<Finding>& findings,
                  const std::vector<models::ReadingResiduals>& before) {
    std::sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
        return a.gain.reduction > b.gain.reduction;
    });
    std::vector<bool> competes;
    for (const Finding& f : findings)
        competes.push_back(!f.fit_compromise && (f.effect.channel.isEmpty() ||
                                                 !explainedByPhysics(f, findings, before)));
    for (std::size_t i = 0; i < findings.size(); ++i) {
        if (!competes[i]) continue;
        const StretchSquares& own = findings[i].gain.stretches;
        double doubt = 1 - probabilityLarger(own, nullptr);
        for (std::size_t j = 0; j < findings.size(); ++j)
            if (j != i && competes[j])
                doubt += 1 - probabilityLarger(own, &findings[j].gain.stretches);
        findings[i].confidence = std::max(0.0, 1 - doubt);
    }
}

/// An effect on the axis that the training runs do not contradict is
/// significant by its confidence, once ranked: held-out runs at other speeds
/// can show a speed law that training runs at close speeds cannot
/// (DiagnosisOptions::min_held_out_confidence).
void admitHeldOutEvidence(std::vector<Finding>& findings, const DiagnosisOptions& options) {
    for (Finding& f : findings)
        if (!f.significant && !f.fit_compromise && f.effect.channel.isEmpty() && f.bic_drop > 0 &&
            f.gain.reduction >= options.min_explained &&
            f.confidence >= options.min_held_out_confidence) {
            f.significant = true;
            f.evidence += QStringLiteral(
                              "; the training runs hardly show it (ΔBIC %1), the held-out "
                              "runs do (confidence %2)")
                              .arg(f.bic_drop, 0, 'f', 0)
                              .arg(f.confidence, 0, 'f', 3);
        }
}

/// The significant finding with the largest gain, or nullptr.
const Finding* bestSignificant(const std::vector<Finding>& findings,
                               const std::vector<models::ReadingResiduals>& before) {
    for (const auto& f : findings)
        if (f.significant &&
            (f.effect.channel.isEmpty() || !explainedByPhysics(f, findings, before)))
            return &f;
    return nullptr;
}

/// The second cause on top of `first`: the best significant finding that
/// removes at least min_second_gain of what the first leaves; a sensor effect
/// on a sensor other than the first cause's quantity is held to the first
/// cause's standard on it (explainsMostOfItsSensor).
const Finding* secondCause(const std::vector<Finding>& second, const Finding& first,
                           const std::vector<models::ReadingResiduals>& before,
                           const DiagnosisOptions& options) {
    for (const auto& f : second) {
        if (!f.significant || f.gain.reduction < options.min_second_gain) continue;
        if (f.effect.channel.isEmpty()) return &f;
        if (explainedByPhysics(f, second, before)) continue;
        if (f.effect.channel == first.effect.channel ||
            explainsMostOfItsSensor(f, before, options.min_explained))
            return &f;
    }
    return nullptr;
}

}  // namespace driftlab::diagnosis
