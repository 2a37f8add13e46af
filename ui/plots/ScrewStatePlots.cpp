#include "ui/plots/ScrewStatePlots.h"

#include "ui/plots/PngPlots.h"

namespace driftlab::ui {

void ScrewStateRecorder::record(const physics::ScrewThermalModel& screw) {
    const auto& cells = screw.temperatures_C();
    if (m_time_h.empty()) {
        m_initial_C = cells.front();
        for (int i = 0; i < static_cast<int>(cells.size()); ++i)
            m_cellAxis_mm.push_back(screw.parameters().fixed_end_axis_mm +
                                    screw.cellCentre_m(i) * 1e3);
    }
    m_time_h.push_back(screw.time_s() / 3600);
    for (double c : cells) m_rise_K.push_back(c - m_initial_C);
    if (screw.time_s() + 1e-9 >= m_nextCurve_s) {
        ErrorCurve curve{screw.time_s() / 3600, {}, {}};
        const int points = 71;
        for (int k = 0; k < points; ++k)
            curve.position_mm.push_back(m_from_mm + (m_to_mm - m_from_mm) * k / (points - 1));
        curve.error_um = screw.thermalError_um(curve.position_mm);
        m_curves.push_back(std::move(curve));
        m_nextCurve_s += m_curveInterval_s;
    }
}

bool ScrewStateRecorder::saveTemperatureMap(const QString& path, const QString& title,
                                            QString* error) const {
    MapPlot plot{title,
                 QStringLiteral("position along the screw (axis mm)"),
                 QStringLiteral("time (h)"),
                 QStringLiteral("temperature rise (K)"),
                 m_cellAxis_mm,
                 m_time_h,
                 m_rise_K};
    return saveMapPng(plot, path, error);
}

bool ScrewStateRecorder::saveThermalErrorCurves(const QString& path, const QString& title,
                                                QString* error) const {
    CurvePlot plot{
        title, QStringLiteral("axis position (mm)"), QStringLiteral("thermal error E (µm)"), {}};
    for (const auto& c : m_curves)
        plot.curves.push_back({QStringLiteral("t = %1 h").arg(c.time_h, 0, 'f', 1), c.position_mm,
                               c.error_um, false});
    return saveCurvesPng(plot, path, error);
}

}  // namespace driftlab::ui
