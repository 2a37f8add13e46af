#include "ui/widgets/Iso230_3Plot.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>
#include <map>

namespace driftlab::ui {
namespace {

/// Distinct colours for up to ten curves, then repeated.
QColor curveColour(int i) {
    static const QColor palette[] = {{0x1f, 0x77, 0xb4}, {0xd6, 0x27, 0x28}, {0x2c, 0xa0, 0x2c},
                                     {0xff, 0x7f, 0x0e}, {0x94, 0x67, 0xbd}, {0x8c, 0x56, 0x4b},
                                     {0xe3, 0x77, 0xc2}, {0x7f, 0x7f, 0x7f}, {0xbc, 0xbd, 0x22},
                                     {0x17, 0xbe, 0xcf}};
    return palette[i % 10];
}

void setUpPlot(QCustomPlot* plot, const QString& x, const QString& y) {
    plot->xAxis->setLabel(x);
    plot->yAxis->setLabel(y);
    plot->legend->setFont(QFont(plot->font().family(), 8));
    plot->legend->setRowSpacing(-3);
    // Top right: a warm-up then cool-down run's drift is low there.
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot->setMinimumSize(300, 220);
}

void addCurve(QCustomPlot* plot, const QString& name, const std::vector<double>& x,
              const std::vector<double>& y, const QPen& pen, bool scatter) {
    QCPGraph* graph = plot->addGraph();
    graph->setName(name);
    graph->setData(QVector<double>(x.begin(), x.end()), QVector<double>(y.begin(), y.end()), true);
    graph->setPen(pen);
    if (scatter) graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 4));
}

void resetPlot(QCustomPlot* plot) {
    plot->clearPlottables();
    plot->clearItems();
    // A colour scale is a layout element: remove it with the map it served.
    for (int i = plot->plotLayout()->elementCount() - 1; i > 0; --i)
        if (qobject_cast<QCPColorScale*>(plot->plotLayout()->elementAt(i)))
            plot->plotLayout()->removeAt(i);
    plot->plotLayout()->simplify();
    plot->xAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    plot->yAxis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
}

}  // namespace

Iso230_3Plot::Iso230_3Plot(QWidget* parent)
    : QWidget(parent),
      m_series(new QCustomPlot(this)),
      m_side(new QCustomPlot(this)),
      m_direction(new QComboBox(this)) {
    setUpPlot(m_series, tr("Time since the run's start (s)"), tr("Drift (µm)"));
    // The legend beside the curves: a dozen targets inside would hide them.
    m_series->plotLayout()->addElement(0, 1, m_series->legend);
    m_series->plotLayout()->setColumnStretchFactor(1, 0.001);
    m_series->legend->setMargins(QMargins(6, 4, 6, 4));
    m_series->legend->setBorderPen(Qt::NoPen);
    m_direction->addItem(tr("+ approach"), int(Direction::Positive));
    m_direction->addItem(tr("− approach"), int(Direction::Negative));
    m_direction->setToolTip(tr("The approach direction the drift map shows"));
    auto* sideBox = new QWidget(this);
    auto* sideBar = new QHBoxLayout;
    sideBar->addWidget(new QLabel(tr("Drift map"), sideBox));
    sideBar->addWidget(m_direction);
    sideBar->addStretch(1);
    auto* sideLayout = new QVBoxLayout(sideBox);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addLayout(sideBar);
    sideLayout->addWidget(m_side, 1);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_series);
    split->addWidget(sideBox);
    split->setSizes({560, 440});
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);
    connect(m_direction, &QComboBox::currentIndexChanged, this, &Iso230_3Plot::showDriftMap);
    clear();
}

void Iso230_3Plot::clear() {
    m_axis.reset();
    resetPlot(m_series);
    resetPlot(m_side);
    m_series->legend->setVisible(false);
    m_side->legend->setVisible(false);
    m_series->replot();
    m_side->replot();
}

int Iso230_3Plot::seriesCount() const {
    return m_series->graphCount();
}

bool Iso230_3Plot::hasDriftMap() const {
    return m_side->plottableCount() == 1 && qobject_cast<QCPColorMap*>(m_side->plottable(0));
}

int Iso230_3Plot::driftMapCells() const {
    if (!hasDriftMap()) return 0;
    const QCPColorMapData* d = static_cast<QCPColorMap*>(m_side->plottable(0))->data();
    return d->keySize() * d->valueSize();
}

int Iso230_3Plot::temperatureCount() const {
    return m_axis ? 0 : m_side->graphCount();
}

void Iso230_3Plot::show(const Campaign& campaign, const Run& run, const iso::RunDrift& drift) {
    clear();
    if (!drift.ok()) return;
    m_direction->setEnabled(bool(drift.axis));
    if (drift.axis) {
        // One colour per target, the same for both approaches.
        std::map<double, int> colourOf;
        for (const iso::TargetDrift& t : drift.axis->targets)
            colourOf.emplace(t.target_mm, int(colourOf.size()));
        for (const iso::TargetDrift& t : drift.axis->targets) {
            const bool up = t.direction == Direction::Positive;
            addCurve(
                m_series, tr("%1 mm").arg(t.target_mm), t.drift.time_s, t.drift.drift_um,
                QPen(curveColour(colourOf[t.target_mm]), 1.5, up ? Qt::SolidLine : Qt::DashLine),
                true);
            if (!up) m_series->graph()->removeFromLegend();
        }
        m_series->legend->setVisible(colourOf.size() <= 12);
        m_series->yAxis->setLabel(tr("Drift (µm): + approach solid, − dashed"));
        m_axis = drift.axis;
        showDriftMap();
    } else {
        m_series->yAxis->setLabel(tr("Drift (µm)"));
        int i = 0;
        for (const iso::ProbeDrift& p : drift.probes->probes)
            addCurve(m_series, p.channel_id, p.drift.time_s, p.drift.drift_um,
                     QPen(curveColour(i++), 1.5), false);
        for (const iso::TiltDrift& t : drift.probes->tilts)
            addCurve(m_series, tr("tilt %1 (%2−%3)").arg(t.name, t.to, t.from), t.drift.time_s,
                     t.drift.drift_um, QPen(curveColour(i++), 1.5, Qt::DashLine), false);
        m_series->legend->setVisible(true);
        // The temperatures beside the probes: what drove the drift.
        setUpPlot(m_side, tr("Time since the run's start (s)"), tr("Temperature (°C)"));
        int k = 0;
        for (const Channel& c : campaign.channels) {
            const int column = run.samples.columnIndex(c.id);
            if (c.quantity != Quantity::Temperature || column < 0) continue;
            addCurve(m_side, c.id, run.samples.time_s, run.samples.values[std::size_t(column)],
                     QPen(curveColour(k++), 1.2), false);
        }
        m_side->legend->setVisible(k > 0);
        m_side->rescaleAxes();
        m_side->replot();
    }
    m_series->rescaleAxes();
    m_series->yAxis->scaleRange(1.1, m_series->yAxis->range().center());
    m_series->replot();
}

void Iso230_3Plot::showDriftMap() {
    if (!m_axis) return;
    resetPlot(m_side);
    setUpPlot(m_side, tr("Target position (mm)"), tr("Cycle (its mean time, s)"));
    const Direction wanted = Direction(m_direction->currentData().toInt());
    std::vector<const iso::TargetDrift*> targets;
    for (const iso::TargetDrift& t : m_axis->targets)
        if (t.direction == wanted) targets.push_back(&t);
    if (targets.empty()) return m_side->replot();
    // Rows are cycles, labelled with the mean time of the cycle over the
    // targets; columns are targets by index, labelled with their position
    // (ISO 230-2 spaces targets unevenly on purpose): every cell is a reading.
    std::map<int, std::pair<double, int>> cycleTime;  // cycle → (sum of times, count)
    for (const iso::TargetDrift* t : targets)
        for (std::size_t i = 0; i < t->cycles.size(); ++i) {
            auto& [sum, n] = cycleTime[t->cycles[i]];
            sum += t->drift.time_s[i];
            ++n;
        }
    std::map<int, int> rowOf;
    for (const auto& [cycle, time] : cycleTime) rowOf.emplace(cycle, int(rowOf.size()));
    const int columns = int(targets.size()), rows = int(rowOf.size());
    auto* map = new QCPColorMap(m_side->xAxis, m_side->yAxis);
    map->data()->setSize(columns, rows);
    map->data()->setRange(QCPRange(0, columns - 1), QCPRange(0, rows - 1));
    for (int c = 0; c < columns; ++c)
        for (int r = 0; r < rows; ++r) map->data()->setCell(c, r, std::nan(""));
    for (int c = 0; c < columns; ++c) {
        const iso::TargetDrift* t = targets[std::size_t(c)];
        for (std::size_t i = 0; i < t->cycles.size(); ++i)
            map->data()->setCell(c, rowOf[t->cycles[i]], t->drift.drift_um[i]);
    }
    auto* scale = new QCPColorScale(m_side);
    m_side->plotLayout()->addElement(0, 1, scale);
    scale->setLabel(tr("Drift (µm)"));
    map->setColorScale(scale);
    map->setGradient(QCPColorGradient(QCPColorGradient::gpJet));
    map->setInterpolate(false);
    map->rescaleDataRange(true);
    auto* margins = new QCPMarginGroup(m_side);
    m_side->axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    scale->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    QSharedPointer<QCPAxisTickerText> targetTicks(new QCPAxisTickerText);
    const int step = (columns + 5) / 6;  // at most six labels: positions need room
    for (int c = 0; c < columns; c += step)
        targetTicks->addTick(c, QString::number(targets[std::size_t(c)]->target_mm, 'g', 6));
    m_side->xAxis->setTicker(targetTicks);
    QSharedPointer<QCPAxisTickerText> cycleTicks(new QCPAxisTickerText);
    for (const auto& [cycle, time] : cycleTime)
        cycleTicks->addTick(rowOf[cycle], QString::number(time.first / time.second, 'f', 0));
    m_side->yAxis->setTicker(cycleTicks);
    m_side->xAxis->setRange(-0.5, columns - 0.5);
    m_side->yAxis->setRange(-0.5, rows - 0.5);
    m_side->replot();
}

}  // namespace driftlab::ui
