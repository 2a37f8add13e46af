#include "ui/widgets/SensorFlagTimeline.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace driftlab::ui {
namespace {

QColor kindColour(sensors::SensorFault fault) {
    switch (fault) {
        case sensors::SensorFault::OutOfRange:
            return {0xc0, 0x1c, 0x28};
        case sensors::SensorFault::Frozen:
            return {0x1c, 0x71, 0xd8};
        case sensors::SensorFault::Spike:
            return {0xe6, 0x61, 0x00};
        case sensors::SensorFault::RateOfChange:
            return {0x81, 0x3d, 0x9c};
        case sensors::SensorFault::RedundantDrift:
            return {0x26, 0xa2, 0x69};
    }
    return Qt::gray;
}

QString kindWords(sensors::SensorFault fault) {
    switch (fault) {
        case sensors::SensorFault::OutOfRange:
            return SensorFlagTimeline::tr("open/short (out of range)");
        case sensors::SensorFault::Frozen:
            return SensorFlagTimeline::tr("frozen");
        case sensors::SensorFault::Spike:
            return SensorFlagTimeline::tr("spike");
        case sensors::SensorFault::RateOfChange:
            return SensorFlagTimeline::tr("rate of change");
        case sensors::SensorFault::RedundantDrift:
            return SensorFlagTimeline::tr("redundant pair diverges");
    }
    return {};
}

}  // namespace

SensorFlagTimeline::SensorFlagTimeline(QWidget* parent)
    : QWidget(parent), m_plot(new QCustomPlot(this)) {
    m_plot->xAxis->setLabel(tr("Time since the run's start (s)"));
    m_plot->yAxis->setRangeReversed(true);  // the first channel on top
    m_plot->yAxis->grid()->setVisible(false);
    m_plot->legend->setFont(QFont(m_plot->font().family(), 8));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->axisRect()->setRangeDrag(Qt::Horizontal);
    m_plot->axisRect()->setRangeZoom(Qt::Horizontal);
    m_plot->setMinimumSize(400, 200);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    clear();
}

void SensorFlagTimeline::clear() {
    m_plot->clearItems();
    m_plot->clearPlottables();
    m_plot->legend->setVisible(false);
    m_rows = m_leftOut = m_kept = 0;
    m_plot->replot();
}

void SensorFlagTimeline::show(const Campaign& campaign, const Run& run,
                              const std::vector<ShownFlag>& flags) {
    clear();
    QSharedPointer<QCPAxisTickerText> ticks(new QCPAxisTickerText);
    std::map<QString, int> rowOf;
    for (const Channel& c : campaign.channels)
        if (run.samples.columnIndex(c.id) >= 0) {
            ticks->addTick(int(rowOf.size()), c.id);
            rowOf.emplace(c.id, int(rowOf.size()));
        }
    m_rows = int(rowOf.size());
    m_plot->yAxis->setTicker(ticks);
    m_plot->yAxis->setRange(-0.7, std::max(1, m_rows) - 0.3);
    const std::vector<double>& t = run.samples.time_s;
    const double start = t.empty() ? 0 : t.front(), end = t.empty() ? 1 : t.back();
    m_plot->xAxis->setRange(start, std::max(end, start + 1));
    // A bar at least 0.8 % of the run wide: a one-sample spike stays visible.
    const double minWidth = 0.008 * (end - start);
    std::map<sensors::SensorFault, bool> inLegend;
    // Kept stretches drawn last: their outline stays visible over a filled one.
    std::vector<ShownFlag> ordered = flags;
    std::stable_partition(ordered.begin(), ordered.end(),
                          [](const ShownFlag& f) { return !f.flag.kept; });
    for (const ShownFlag& shown : ordered) {
        const auto row = rowOf.find(shown.flag.range.channel);
        if (row == rowOf.end()) continue;
        const sensors::FlaggedRange& r = shown.flag.range;
        const double mid = 0.5 * (r.from_s + r.to_s),
                     half = 0.5 * std::max(r.to_s - r.from_s, minWidth);
        auto* bar = new QCPItemRect(m_plot);
        bar->topLeft->setCoords(mid - half, row->second - 0.35);
        bar->bottomRight->setCoords(mid + half, row->second + 0.35);
        const QColor colour = kindColour(r.fault);
        bar->setPen(QPen(colour, shown.flag.kept ? 1.5 : 1,
                         shown.flag.kept ? Qt::DashLine : Qt::SolidLine));
        bar->setBrush(shown.flag.kept ? QBrush(Qt::NoBrush) : QBrush(colour));
        ++(shown.flag.kept ? m_kept : m_leftOut);
        // The legend names the kinds shown (an empty graph carries the entry).
        if (!inLegend[r.fault]) {
            inLegend[r.fault] = true;
            QCPGraph* entry = m_plot->addGraph();
            entry->setName(kindWords(r.fault));
            entry->setPen(QPen(colour, 6));
        }
    }
    if (m_kept > 0) {
        QCPGraph* entry = m_plot->addGraph();
        entry->setName(tr("outlined: kept, used in the fits"));
        entry->setPen(QPen(Qt::darkGray, 1.5, Qt::DashLine));
    }
    m_plot->legend->setVisible(!inLegend.empty());
    m_plot->replot();
}

}  // namespace driftlab::ui
