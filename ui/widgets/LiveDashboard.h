#pragma once
// The live dashboard of a run (docs/gui-run.md; its redraw budget in docs/benchmarks.md):
// temperatures and the axis position over run time, the interferometer's deviation per target
// coloured by cycle, and the thermal-error map (deviation over target × time). A timer pulls at ≤
// 25 Hz from the live read path — never per sample — and draws min/max envelopes per time bucket
// from LiveSampleBuffer::summary, so an 8- or 24-hour run of 64 channels costs a few hundred chunk
// summaries per channel and redraw; the rows stay in the buffer and the store, the plots hold only
// bucket min/max.

#include <QTimer>
#include <QWidget>
#include <functional>
#include <memory>

#include "acquisition/live/LiveReadings.h"
#include "acquisition/live/LiveSampleBuffer.h"

class QCustomPlot;
class QCPColorMap;

namespace driftlab::ui {

struct LiveSources {
    std::shared_ptr<const live::LiveSampleBuffer> rows;
    std::shared_ptr<const live::LiveReadings> readings;
};

class LiveDashboard : public QWidget {
    Q_OBJECT
public:
    explicit LiveDashboard(QWidget* parent = nullptr);

    /// Where the timer pulls from: called on each tick (cheap: two shared pointers).
    void setSources(std::function<LiveSources()> sources) { m_sources = std::move(sources); }
    /// Columns plotted as temperatures; empty: every column but the axis ones.
    void setTemperatureColumns(const QStringList& columns) { m_temperatureColumns = columns; }
    /// Pulls on a timer at `hz` (≤ 25) while on; off keeps what is drawn.
    void setLive(bool on, int hz = 25);
    /// Pulls what is new and replots; `force` redraws even when nothing arrived.
    /// Returns whether the plots changed.
    bool refresh(bool force = false);
    /// refresh(true) and paint now (the benchmark's redraw).
    void redrawNow();
    /// Buckets per plot width (the envelope's resolution).
    static constexpr int kBuckets = 400;
    /// From this many rows on, buckets are whole chunks (cheap summaries).
    static constexpr std::int64_t kAlignedFromRows = 16'384;

private:
    void clearPlots();
    void drawRows(const live::LiveSampleBuffer& buffer);
    void drawReadings(const std::vector<PositioningMeasurement>& fresh);
    void drawErrorMap();

    QCustomPlot *m_temperatures, *m_position, *m_readingsPlot, *m_mapPlot;
    QCPColorMap* m_map = nullptr;
    QTimer m_timer;
    std::function<LiveSources()> m_sources;
    QStringList m_temperatureColumns;
    const live::LiveSampleBuffer* m_shownBuffer = nullptr;
    const live::LiveReadings* m_shownReadings = nullptr;
    std::int64_t m_rowsDrawn = 0;
    std::size_t m_readingsDrawn = 0;
    std::vector<PositioningMeasurement> m_readings;  // few: one per target and cycle
};

}  // namespace driftlab::ui
