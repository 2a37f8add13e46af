#include "ui/plots/DiagnosisPlots.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "ui/plots/PngPlots.h"

namespace driftlab::ui {

MapPlot residualMapPlot(const models::ReadingResiduals& residuals, const QString& title) {
    // Pass k ↔ its mean reading time; target ↔ position. Both directions averaged.
    std::map<double, std::map<double, std::pair<double, int>>> byTime;  // pass start → x → (Σ, n)
    std::vector<double> times;
    for (std::size_t j = 0; j < residuals.points.size(); ++j)
        times.push_back(residuals.points[j].time_s);
    std::sort(times.begin(), times.end());
    // Readings more than 5 min apart belong to different passes.
    std::vector<double> passStarts;
    for (double t : times)
        if (passStarts.empty() || t - passStarts.back() > 300) passStarts.push_back(t);
    std::set<double> targets;
    for (std::size_t j = 0; j < residuals.points.size(); ++j) {
        const auto& p = residuals.points[j];
        const double pass =
            *std::prev(std::upper_bound(passStarts.begin(), passStarts.end(), p.time_s));
        auto& cell = byTime[pass][p.position_mm];
        cell.first += residuals.error_um[j];
        cell.second += 1;
        targets.insert(p.position_mm);
    }
    MapPlot plot{title,
                 QStringLiteral("axis position (mm)"),
                 QStringLiteral("time (h)"),
                 QStringLiteral("measured − model (µm)"),
                 {targets.begin(), targets.end()},
                 {},
                 {}};
    for (const auto& [pass, row] : byTime) {
        plot.y.push_back(pass / 3600);
        for (double x : plot.x) {
            auto it = row.find(x);
            plot.z.push_back(it == row.end() ? 0.0 : it->second.first / it->second.second);
        }
    }
    return plot;
}

bool saveResidualMap(const models::ReadingResiduals& residuals, const QString& path,
                     const QString& title, QString* error) {
    return saveMapPng(residualMapPlot(residuals, title), path, error);
}

CurvePlot beforeAfterPlot(const models::RunData& run, const models::ReadingResiduals& base,
                          const models::ReadingResiduals* adopted, const QString& adoptedName,
                          const QString& title) {
    double far = -INFINITY;
    for (const auto& p : base.points) far = std::max(far, p.position_mm);
    Curve measured{QStringLiteral("measured"), {}, {}, true};
    Curve before{QStringLiteral("base model"), {}, {}, false};
    Curve after{adoptedName, {}, {}, false};
    for (std::size_t j = 0; j < base.points.size(); ++j) {
        if (base.points[j].position_mm != far ||
            run.observations[j].direction != Direction::Positive)
            continue;
        const double t_h = base.points[j].time_s / 3600;
        const double e = run.observations[j].error_um;
        measured.x.push_back(t_h);
        measured.y.push_back(e);
        before.x.push_back(t_h);
        before.y.push_back(e - base.error_um[j]);
        if (adopted) {
            after.x.push_back(t_h);
            after.y.push_back(e - adopted->error_um[j]);
        }
    }
    CurvePlot plot{title,
                   QStringLiteral("time (h)"),
                   QStringLiteral("thermal error at %1 mm (µm)").arg(far, 0, 'f', 0),
                   {measured, before}};
    if (adopted) plot.curves.push_back(after);
    return plot;
}

bool saveBeforeAfter(const models::RunData& run, const models::ReadingResiduals& base,
                     const models::ReadingResiduals* adopted, const QString& adoptedName,
                     const QString& path, const QString& title, QString* error) {
    return saveCurvesPng(beforeAfterPlot(run, base, adopted, adoptedName, title), path, error);
}

}  // namespace driftlab::ui
