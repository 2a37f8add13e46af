#include "ui/widgets/RunStatusWidget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <cmath>

#include "ui/models/DeviceHealthModel.h"

namespace driftlab::ui {

QString clockText(double seconds) {
    const qint64 s = qint64(std::llround(std::max(0.0, seconds)));
    return QStringLiteral("%1:%2:%3")
        .arg(s / 3600)
        .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(s % 60, 2, 10, QLatin1Char('0'));
}

RunStatusWidget::RunStatusWidget(DeviceHealthModel& health, QWidget* parent)
    : QWidget(parent),
      m_health(health),
      m_state(new QLabel(this)),
      m_elapsed(new QLabel(this)),
      m_next(new QLabel(this)),
      m_lights(new QHBoxLayout) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 0, 4, 0);
    for (QLabel* l : {m_state, m_elapsed, m_next}) layout->addWidget(l);
    layout->addLayout(m_lights);
    layout->addStretch(1);
    connect(&m_health, &QAbstractItemModel::modelReset, this, &RunStatusWidget::rebuildLights);
    connect(&m_health, &QAbstractItemModel::rowsInserted, this, &RunStatusWidget::rebuildLights);
    connect(&m_health, &QAbstractItemModel::dataChanged, this, &RunStatusWidget::rebuildLights);
    showRun(engine::EngineState::Idle, 0, std::nullopt);
}

void RunStatusWidget::showRun(engine::EngineState state, double elapsed_s,
                              std::optional<double> next_s) {
    m_state->setText(tr("Run: <b>%1</b>").arg(toString(state)));
    m_elapsed->setText(tr("elapsed %1").arg(clockText(elapsed_s)));
    m_next->setText(next_s ? tr("next measurement at %1").arg(clockText(*next_s))
                           : tr("no measurement due"));
}

QString RunStatusWidget::text() const {
    QStringList parts{m_state->text(), m_elapsed->text(), m_next->text()};
    for (int row = 0; row < m_health.rowCount(); ++row)
        parts << m_health.data(m_health.index(row, 0), Qt::DisplayRole).toString() +
                     QLatin1Char('=') +
                     m_health.data(m_health.index(row, 1), Qt::DisplayRole).toString();
    return parts.join(QLatin1Char(' '));
}

void RunStatusWidget::rebuildLights() {
    while (QLayoutItem* item = m_lights->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    for (int row = 0; row < m_health.rowCount(); ++row) {
        auto* light = new QLabel(this);
        const QColor colour = DeviceHealthModel::colourOf(m_health.health(row));
        light->setFixedSize(12, 12);
        light->setStyleSheet(
            QStringLiteral("background:%1; border-radius:6px;").arg(colour.name()));
        light->setToolTip(m_health.data(m_health.index(row, 0), Qt::ToolTipRole).toString());
        m_lights->addWidget(light);
    }
}

}  // namespace driftlab::ui
