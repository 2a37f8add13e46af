#include "ui/plots/HistoryPlot.h"

#include <cmath>

namespace driftlab::ui {

CurvePlot historyTrendPlot(const history::MachineHistory& history) {
    CurvePlot plot;
    plot.title = QStringLiteral("%1 axis %2: ISO 230-2 figures per campaign")
                     .arg(history.machine, history.axis);
    plot.xLabel = QStringLiteral("Campaign date (UTC)");
    plot.yLabel = QStringLiteral("µm");
    plot.xIsDate = true;
    for (history::Figure f : history::kFigures) {
        Curve curve;
        curve.name =
            QStringLiteral("%1 (%2)").arg(history::figureName(f), history::figureMeaning(f));
        for (const history::HistoryEntry& e : history.entries) {
            const double value = e.positioning.value_um(f);
            if (!std::isfinite(value)) continue;
            // Seconds since 1970, as QCPAxisTickerDateTime reads a key.
            curve.x.push_back(double(e.date.utc.toMSecsSinceEpoch()) / 1000.0);
            curve.y.push_back(value);
        }
        plot.curves.push_back(std::move(curve));
    }
    return plot;
}

}  // namespace driftlab::ui
