#pragma once
// The compensation table over the axis: the corrections for both approaches,
// and, once read, the controller's active table and the change a push makes.

#include <QWidget>
#include <optional>

#include "acquisition/push/ActiveTableRead.h"
#include "core/compensation/CompensationTable.h"

class QCustomPlot;

namespace driftlab::ui {

class CompensationPlot : public QWidget {
    Q_OBJECT
public:
    explicit CompensationPlot(QWidget* parent = nullptr);

    void show(const compensation::CompensationTable& table,
              const std::optional<push::TableChange>& change);
    void clear();
    /// Graphs drawn now (for tests): corrections, active, change.
    int graphCount() const;

private:
    QCustomPlot* m_plot;
};

}  // namespace driftlab::ui
