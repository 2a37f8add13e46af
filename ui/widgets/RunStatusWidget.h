#pragma once
// The run's line in the status bar: state, elapsed, the next measurement's
// run time, and one health light per device (green, amber, red) from the
// device health model.

#include <QWidget>

#include "acquisition/engine/ProcedureEngine.h"

class QLabel;
class QHBoxLayout;

namespace driftlab::ui {

class DeviceHealthModel;

class RunStatusWidget : public QWidget {
    Q_OBJECT
public:
    RunStatusWidget(DeviceHealthModel& health, QWidget* parent = nullptr);

    void showRun(engine::EngineState state, double elapsed_s, std::optional<double> next_s);
    QString text() const;

private:
    void rebuildLights();

    DeviceHealthModel& m_health;
    QLabel* m_state;
    QLabel* m_elapsed;
    QLabel* m_next;
    QHBoxLayout* m_lights;
};

/// h:mm:ss of a duration.
QString clockText(double seconds);

}  // namespace driftlab::ui
