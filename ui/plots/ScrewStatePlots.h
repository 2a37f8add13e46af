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
        : curveInterval_s_(curve_interval_s), from_mm_(from_mm), to_mm_(to_mm) {}

    /// Called at every logged sample.
    void record(const physics::ScrewThermalModel& screw);

    /// Temperature rise over position × time (PNG).
    bool saveTemperatureMap(const QString& path, const QString& title, QString* error) const;
    /// Thermal error vs position, one curve per interval (PNG).
    bool saveThermalErrorCurves(const QString& path, const QString& title, QString* error) const;

private:
    double curveInterval_s_, from_mm_, to_mm_;
    double nextCurve_s_ = 0;
    double initial_C_ = 0;
    std::vector<double> cellAxis_mm_;
    std::vector<double> time_h_;
    std::vector<double> rise_K_;  ///< row per time, column per cell
    struct ErrorCurve {
        double time_h;
        std::vector<double> position_mm, error_um;
    };
    std::vector<ErrorCurve> curves_;
};

}  // namespace driftlab::ui
