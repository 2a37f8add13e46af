#pragma once
// A run's channels over time with their sensor flags: one row per channel,
// a bar per flagged stretch coloured by kind (open/short, frozen, spike, rate,
// redundancy). A stretch the models leave out is filled; a kept one is only
// outlined, so what a fit will not see stands out.

#include <QWidget>
#include <vector>

#include "core/domain/Campaign.h"
#include "ui/shell/SensorFlagJob.h"

class QCustomPlot;

namespace driftlab::ui {

class SensorFlagTimeline : public QWidget {
    Q_OBJECT
public:
    explicit SensorFlagTimeline(QWidget* parent = nullptr);

    /// Shows the channels of `run` (a run of `campaign`) and `flags`.
    void show(const Campaign& campaign, const Run& run, const std::vector<ShownFlag>& flags);
    void clear();

    /// The channel rows and the stretches drawn, filled (left out) or outlined (kept).
    int channelRows() const { return m_rows; }
    int leftOutBars() const { return m_leftOut; }
    int keptBars() const { return m_kept; }

private:
    QCustomPlot* m_plot;
    int m_rows = 0, m_leftOut = 0, m_kept = 0;
};

}  // namespace driftlab::ui
