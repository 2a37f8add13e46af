#include "ui/widgets/LiveDashboard.h"

#include <qcustomplot.h>

#include <QGridLayout>
#include <cmath>
#include <map>

#include "core/domain/Channel.h"

namespace driftlab::ui {
namespace {

QCustomPlot* makePlot(QWidget* parent, const QString& title, const QString& x, const QString& y) {
    auto* plot = new QCustomPlot(parent);
    plot->plotLayout()->insertRow(0);
    plot->plotLayout()->addElement(
        0, 0, new QCPTextElement(plot, title, QFont(QStringLiteral("sans"), 9, QFont::Bold)));
    plot->xAxis->setLabel(x);
    plot->yAxis->setLabel(y);
    // Envelopes of hundreds of buckets: antialiasing costs more than it shows.
    plot->setNotAntialiasedElements(QCP::aeAll);
    plot->setMinimumSize(280, 180);
    return plot;
}

bool isAxisColumn(const QString& c) {
    return c == kPositionColumn || c == kFeedColumn || c == kTorqueColumn;
}

/// The min/max envelope of `summary` as a zig-zag line (min then max per bucket).
QVector<QCPGraphData> envelope(const live::LiveSummary& summary) {
    QVector<QCPGraphData> points;
    points.reserve(int(summary.buckets.size()) * 2);
    for (const live::LiveBucket& b : summary.buckets) {
        if (b.range.present == 0) continue;
        const double mid_min = (b.from_s + b.to_s) / 2 / 60;
        points.append({mid_min, b.range.min});
        points.append({mid_min, b.range.max});
    }
    return points;
}

QColor cycleColour(int cycle) {
    // Early cycles blue, later ones towards red: the drift reads as a colour.
    return QColor::fromHsv((240 - 27 * cycle % 240 + 360) % 360, 200, 200);
}

}  // namespace

LiveDashboard::LiveDashboard(QWidget* parent) : QWidget(parent) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    m_temperatures = makePlot(this, tr("Temperatures"), tr("run time (min)"), tr("°C"));
    m_position = makePlot(this, tr("Axis position"), tr("run time (min)"), tr("mm"));
    m_readingsPlot = makePlot(this, tr("Interferometer: deviation per target, by cycle"),
                              tr("target (mm)"), tr("deviation (µm)"));
    m_mapPlot = makePlot(this, tr("Thermal error over position × time"), tr("target (mm)"),
                         tr("run time (min)"));
    m_map = new QCPColorMap(m_mapPlot->xAxis, m_mapPlot->yAxis);
    QCPColorGradient gradient(QCPColorGradient::gpJet);
    gradient.setNanHandling(QCPColorGradient::nhTransparent);
    m_map->setGradient(gradient);
    auto* scale = new QCPColorScale(m_mapPlot);
    m_mapPlot->plotLayout()->addElement(1, 1, scale);
    scale->setLabel(tr("µm"));
    m_map->setColorScale(scale);
    m_position->addGraph()->setPen(QPen(QColor(0x30, 0x60, 0xc0)));
    grid->addWidget(m_temperatures, 0, 0);
    grid->addWidget(m_readingsPlot, 0, 1);
    grid->addWidget(m_position, 1, 0);
    grid->addWidget(m_mapPlot, 1, 1);
    grid->setRowStretch(0, 3);
    grid->setRowStretch(1, 2);
    connect(&m_timer, &QTimer::timeout, this, [this] { refresh(); });
}

void LiveDashboard::setLive(bool on, int hz) {
    if (!on) {
        m_timer.stop();
        return;
    }
    m_timer.start(1000 / std::clamp(hz, 1, 25));
}

void LiveDashboard::clearPlots() {
    m_temperatures->clearGraphs();
    m_readingsPlot->clearGraphs();
    m_position->graph(0)->data()->clear();
    m_map->data()->clear();
    m_readings.clear();
    m_rowsDrawn = 0;
    m_readingsDrawn = 0;
}

bool LiveDashboard::refresh(bool force) {
    const LiveSources sources = m_sources ? m_sources() : LiveSources{};
    if (sources.rows.get() != m_shownBuffer || sources.readings.get() != m_shownReadings) {
        // A new run: its times restart at 0.
        clearPlots();
        m_shownBuffer = sources.rows.get();
        m_shownReadings = sources.readings.get();
        force = true;
    }
    bool changed = force;
    if (sources.rows && (force || sources.rows->rowCount() != m_rowsDrawn)) {
        drawRows(*sources.rows);
        changed = true;
    }
    if (sources.readings && sources.readings->size() != m_readingsDrawn) {
        drawReadings(sources.readings->since(m_readingsDrawn));
        changed = true;
    }
    if (!changed) return false;
    for (QCustomPlot* plot : {m_temperatures, m_position, m_readingsPlot, m_mapPlot})
        plot->replot(QCustomPlot::rpQueuedReplot);
    return true;
}

void LiveDashboard::redrawNow() {
    refresh(true);
    for (QCustomPlot* plot : {m_temperatures, m_position, m_readingsPlot, m_mapPlot})
        plot->replot(QCustomPlot::rpImmediateRefresh);
}

void LiveDashboard::drawRows(const live::LiveSampleBuffer& buffer) {
    const std::int64_t count = buffer.rowCount();
    m_rowsDrawn = count;
    if (count == 0) return;
    const live::LiveRows last = buffer.rowsSince(count - 1);
    const live::LiveRows first = buffer.rowsSince(buffer.firstHeldRow());
    const double from_s = first.time_s(first.beginRow());
    double to_s = std::max(last.time_s(last.endRow() - 1), from_s + 1e-3);
    // Buckets on chunk boundaries once the run is long: every sealed chunk
    // then lies in one bucket and is taken from its summary, not read row by
    // row (a column read across rows touches a cache line per value).
    int buckets = kBuckets;
    const std::int64_t held = count - buffer.firstHeldRow();
    if (held > kAlignedFromRows) {
        const double chunk_s = (to_s - from_s) / double(held - 1) * live::LiveChunk::kCapacityRows;
        const int chunksPerBucket =
            std::max(1, int(std::ceil((to_s - from_s) / chunk_s / kBuckets)));
        const double width_s = chunksPerBucket * chunk_s;
        buckets = std::max(1, int(std::ceil((to_s - from_s) / width_s)));
        to_s = from_s + buckets * width_s;
    }

    QList<int> columns;
    for (int c = 0; c < buffer.columns().size(); ++c) {
        const QString& name = buffer.columns()[c];
        if (m_temperatureColumns.isEmpty() ? !isAxisColumn(name)
                                           : m_temperatureColumns.contains(name))
            columns << c;
    }
    if (m_temperatures->graphCount() != columns.size()) {
        m_temperatures->clearGraphs();
        for (int i = 0; i < columns.size(); ++i) {
            QCPGraph* g = m_temperatures->addGraph();
            g->setName(buffer.columns()[columns[i]]);
            g->setPen(
                QPen(QColor::fromHsv(i * 300 / std::max<qsizetype>(1, columns.size()), 210, 190)));
        }
    }
    for (int i = 0; i < columns.size(); ++i)
        m_temperatures->graph(i)->data()->set(
            envelope(buffer.summary(columns[i], from_s, to_s, buckets)), true);
    const double shownTo_s = last.time_s(last.endRow() - 1);
    m_temperatures->xAxis->setRange(from_s / 60, std::max(shownTo_s, from_s + 1e-3) / 60);
    m_temperatures->yAxis->rescale();
    const int position = buffer.columnIndex(kPositionColumn);
    if (position >= 0)
        m_position->graph(0)->data()->set(envelope(buffer.summary(position, from_s, to_s, buckets)),
                                          true);
    m_position->xAxis->setRange(m_temperatures->xAxis->range());
    m_position->yAxis->rescale();
}

void LiveDashboard::drawReadings(const std::vector<PositioningMeasurement>& fresh) {
    m_readingsDrawn += fresh.size();
    m_readings.insert(m_readings.end(), fresh.begin(), fresh.end());
    for (const PositioningMeasurement& p : fresh) {
        while (m_readingsPlot->graphCount() <= p.cycle) {
            QCPGraph* g = m_readingsPlot->addGraph();
            const int cycle = m_readingsPlot->graphCount() - 1;
            g->setName(tr("cycle %1").arg(cycle));
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, cycleColour(cycle), 5));
        }
        m_readingsPlot->graph(p.cycle)->addData(p.target_mm, p.deviation_um);
    }
    m_readingsPlot->rescaleAxes();
    drawErrorMap();
}

void LiveDashboard::drawErrorMap() {
    // Cells: the distinct targets × the cycles; a cell is the mean deviation of
    // both directions at that target in that cycle, at the cycle's mean time.
    std::map<double, int> targets;
    std::map<int, std::pair<double, int>> cycleTimes;
    for (const PositioningMeasurement& p : m_readings) {
        targets.emplace(std::round(p.target_mm * 1e3) / 1e3, 0);
        auto& [sum_s, n] = cycleTimes[p.cycle];
        sum_s += p.time_s;
        ++n;
    }
    if (targets.size() < 2) return;
    int ix = 0;
    for (auto& [target, index] : targets) index = ix++;
    std::map<int, int> cycleRow;
    for (const auto& [cycle, time] : cycleTimes) cycleRow.emplace(cycle, int(cycleRow.size()));
    const int nx = int(targets.size()), ny = int(cycleRow.size());
    std::vector<double> sum(std::size_t(nx * ny), 0.0);
    std::vector<int> n(sum.size(), 0);
    for (const PositioningMeasurement& p : m_readings) {
        const std::size_t cell =
            std::size_t(cycleRow[p.cycle] * nx + targets[std::round(p.target_mm * 1e3) / 1e3]);
        sum[cell] += p.deviation_um;
        ++n[cell];
    }
    const double t0_min = cycleTimes.begin()->second.first / cycleTimes.begin()->second.second / 60;
    const double t1_min =
        cycleTimes.rbegin()->second.first / cycleTimes.rbegin()->second.second / 60;
    m_map->data()->setSize(nx, ny);
    m_map->data()->setRange(QCPRange(targets.begin()->first, targets.rbegin()->first),
                            ny > 1 ? QCPRange(t0_min, t1_min) : QCPRange(t0_min - 1, t0_min + 1));
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const std::size_t cell = std::size_t(y * nx + x);
            m_map->data()->setCell(x, y, n[cell] ? sum[cell] / n[cell] : std::nan(""));
        }
    m_map->rescaleDataRange(true);
    m_mapPlot->rescaleAxes();
}

}  // namespace driftlab::ui
