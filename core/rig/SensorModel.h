#pragma once
// What a real temperature sensor does to the temperature of its part: a
// first-order lag (thermal contact), a constant offset (calibration), noise,
// quantisation of the module (0.01 K) and occasional dropouts.

#include <cmath>
#include <limits>
#include <random>

namespace driftlab::rig {

struct SensorSpec {
    double lag_s = 0;
    double offset_K = 0;
    double noise_K = 0.02;
    double quantum_K = 0.01;
    double dropout_probability = 0;
};

class SensorModel {
public:
    SensorModel(SensorSpec spec, unsigned seed) : m_spec(spec), m_rng(seed) {}

    /// The reading at a sample `dt_s` after the previous one, of a part at `true_C`.
    /// NaN is a dropout (a missing sample).
    double read(double true_C, double dt_s) {
        if (!m_started || m_spec.lag_s <= 0) {
            m_lagged = true_C;
            m_started = true;
        } else {
            // Exact step of dy/dt = (u - y)/τ for u held over the interval.
            m_lagged = true_C + (m_lagged - true_C) * std::exp(-dt_s / m_spec.lag_s);
        }
        const double noisy = m_lagged + m_spec.offset_K + m_noise(m_rng) * m_spec.noise_K;
        // Divide by the integer steps per kelvin so that 20.07 is written as 20.07.
        const double stepsPerK = m_spec.quantum_K > 0 ? std::round(1.0 / m_spec.quantum_K) : 0;
        const double reading = stepsPerK > 0 ? std::round(noisy * stepsPerK) / stepsPerK : noisy;
        if (m_spec.dropout_probability > 0 && m_uniform(m_rng) < m_spec.dropout_probability)
            return std::numeric_limits<double>::quiet_NaN();
        return reading;
    }

private:
    SensorSpec m_spec;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_noise{0.0, 1.0};
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
    double m_lagged = 0;
    bool m_started = false;
};

}  // namespace driftlab::rig
