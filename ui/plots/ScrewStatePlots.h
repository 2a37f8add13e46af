#pragma once
// What no sensor sees, plotted from the simulation's true state: the
// temperature along the screw over time and the thermal error along the axis
// at intervals. Used by `driftlab-cli simulate --plots` and the docs.

#include <QString>
#include <vector>

#include "core/physics/ScrewThermalModel.h"

namespace driftlab::ui {

class ScrewStateRecorder {
public:
    /// Thermal-error curves every `curve_interval_s`, between `from_mm` and `to_mm`.
    ScrewStateRecorder(double curve_interval_s, double from_mm, double to_mm)
        : m_curveInterval_s(curve_interval_s), m_from_mm(from_mm), m_to_mm(to_mm) {}

    /// Called at every logged sample.
    void record(const physics::ScrewThermalModel& screw);

    /// Temperature rise over position × time (PNG).
    bool saveTemperatureMap(const QString& path, const QString& title, QString* error) const;
    /// Thermal error vs position, one curve per interval (PNG).
    bool saveThermalErrorCurves(const QString& path, const QString& title, QString* error) const;

private:
    double m_curveInterval_s, m_from_mm, m_to_mm;
    double m_nextCurve_s = 0;
    double m_initial_C = 0;
    std::vector<double> m_cellAxis_mm;
    std::vector<double> m_time_h;
    std::vector<double> m_rise_K;  ///< row per time, column per cell
    struct ErrorCurve {
        double time_h;
        std::vector<double> position_mm, error_um;
    };
    std::vector<ErrorCurve> m_curves;
};

}  // namespace driftlab::ui
