#pragma once
// Live compensation over the replayed run's time: the offset sent at each
// update (a step: it holds until the next), the model's prediction with its
// 95 % band, and the stretches in which the machine cut and updates were held.

#include <QWidget>
#include <vector>

#include "core/compensation/LiveThermalCompensation.h"

class QCustomPlot;
class QCPItemRect;

namespace driftlab::ui {

class LiveOffsetPlot : public QWidget {
    Q_OBJECT
public:
    explicit LiveOffsetPlot(QWidget* parent = nullptr);

    /// Draws the updates so far with `uncertainty_um` (NaN: no band).
    void show(const std::vector<compensation::LiveUpdate>& updates, double uncertainty_um);
    /// A stretch of the run in which the machine cut, from_s to to_s.
    void addCut(double from_s, double to_s);
    void clear();
    /// Graphs drawn now (for tests): cut key, band, prediction, offset sent.
    int graphCount() const;
    int cutCount() const { return int(m_cuts.size()); }

private:
    QCustomPlot* m_plot;
    std::vector<QCPItemRect*> m_cuts;
};

}  // namespace driftlab::ui
