#include "ui/plots/ScrewStatePlots.h"

#include "ui/plots/PngPlots.h"

namespace driftlab::ui {

void ScrewStateRecorder::record(const physics::ScrewThermalModel& screw) {
    const auto& cells = screw.temperatures_C();
    if (time_h_.empty()) {
        initial_C_ = cells.front();
        for (int i = 0; i < static_cast<int>(cells.size()); ++i)
            cellAxis_mm_.push_back(screw.parameters().fixed_end_axis_mm +
                                   screw.cellCentre_m(i) * 1e3);
    }
    time_h_.push_back(screw.time_s() / 3600);
    for (double c : cells) rise_K_.push_back(c - initial_C_);
    if (screw.time_s() + 1e-9 >= nextCurve_s_) {
        ErrorCurve curve{screw.time_s() / 3600, {}, {}};
        const int points = 71;
        for (int k = 0; k < points; ++k)
            curve.position_mm.push_back(from_mm_ + (to_mm_ - from_mm_) * k / (points - 1));
        curve.error_um = screw.thermalError_um(curve.position_mm);
        curves_.push_back(std::move(curve));
        nextCurve_s_ += curveInterval_s_;
    }
}

bool ScrewStateRecorder::saveTemperatureMap(const QString& path, const QString& title,
                                            QString* error) const {
    MapPlot plot{title,
                 QStringLiteral("position along the screw (axis mm)"),
                 QStringLiteral("time (h)"),
                 QStringLiteral("temperature rise (K)"),
                 cellAxis_mm_,
                 time_h_,
                 rise_K_};
    return saveMapPng(plot, path, error);
}

bool ScrewStateRecorder::saveThermalErrorCurves(const QString& path, const QString& title,
                                                QString* error) const {
    CurvePlot plot{
        title, QStringLiteral("axis position (mm)"), QStringLiteral("thermal error E (µm)"), {}};
    for (const auto& c : curves_)
        plot.curves.push_back({QStringLiteral("t = %1 h").arg(c.time_h, 0, 'f', 1), c.position_mm,
                               c.error_um, false});
    return saveCurvesPng(plot, path, error);
}

}  // namespace driftlab::ui
