#pragma once
// The ISO 230-3 figures of one run, side by side. A moving run: the drift of
// each target over time (+ approach solid, − approach dashed) and the drift
// map over target × cycle time for one approach (QCPColorMap). A spindle or
// ETVE run: each probe's drift (and the tilts, in µm of differential drift)
// over time, and beside it the run's temperatures over the same time.

#include <QWidget>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/iso/Iso230_3Json.h"

class QComboBox;
class QCustomPlot;

namespace driftlab::ui {

class Iso230_3Plot : public QWidget {
    Q_OBJECT
public:
    explicit Iso230_3Plot(QWidget* parent = nullptr);

    /// Shows `drift` of `run` (a run of `campaign`).
    void show(const Campaign& campaign, const Run& run, const iso::RunDrift& drift);
    void clear();

    /// The drift-over-time curves drawn.
    int seriesCount() const;
    /// Whether the drift map is shown (moving runs) and its cells.
    bool hasDriftMap() const;
    int driftMapCells() const;
    /// The temperature curves beside the probes (spindle and ETVE runs).
    int temperatureCount() const;
    /// "+" or "−": the approach the drift map shows.
    QComboBox* mapDirectionBox() const { return m_direction; }

private:
    void showDriftMap();

    QCustomPlot* m_series;
    QCustomPlot* m_side;
    QComboBox* m_direction;
    std::optional<iso::AxisDriftEvaluation> m_axis;
};

}  // namespace driftlab::ui
