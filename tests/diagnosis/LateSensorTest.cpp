// Undoing a sensor's first-order lag, against closed forms: a sensor that
// reads s(t) through a lag τ saw T = s + τ·ds/dt.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/diagnosis/LateSensor.h"

using driftlab::diagnosis::beforeTheLag;

TEST(LateSensor, aRampLateByTauIsTauTimesItsSlopeAhead) {
    // Uneven sampling, 4–6 s apart; a line's slope is exact in any window.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> gap(4, 6);
    std::vector<double> t{0}, s{0};
    while (t.back() < 4 * 3600) {
        t.push_back(t.back() + gap(rng));
        s.push_back(2e-4 * t.back());  // 0.72 K/h
    }
    const auto seen = beforeTheLag(t, s, 900);
    for (std::size_t k = 0; k < t.size(); k += 37)
        EXPECT_NEAR(seen[k], s[k] + 900 * 2e-4, 1e-9) << "t = " << t[k];
}

TEST(LateSensor, aNoisySlowSwingComesBackWithinItsNoise) {
    // A room swinging 0.5 K over 12 h read 20 min late, 0.02 K noise, every 5 s.
    const double w = 2 * M_PI / (12 * 3600), tau = 1200;
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0, 0.02);
    std::vector<double> t, s;
    for (double time = 0; time <= 6 * 3600; time += 5) {
        t.push_back(time);
        s.push_back(0.5 * std::sin(w * time) + noise(rng));
    }
    const auto seen = beforeTheLag(t, s, tau);
    double worst = 0;
    for (std::size_t k = 120; k + 120 < t.size(); ++k) {  // full windows
        const double correction = tau * 0.5 * w * std::cos(w * t[k]);
        worst = std::max(worst, std::abs(seen[k] - s[k] - correction));
    }
    // The correction τ·ds/dt is up to 0.087 K; over 4000 readings its error
    // stays within 5σ of the slope's noise over ±10 min (σ ≈ 0.0045 K).
    EXPECT_LT(worst, 0.025);
}

TEST(LateSensor, noLagOrTooFewReadingsChangeNothing) {
    const std::vector<double> t{0, 5, 10}, s{1, 2, 4};
    EXPECT_EQ(beforeTheLag(t, s, 0), s);
    EXPECT_EQ(beforeTheLag({0, 5}, {1, 2}, 600), std::vector<double>({1, 2}));
}
