#pragma once
// The ISO 230-2 figure: the mean positional deviation over the target
// position for both approaches, with x̄ ± k·s as error bars (k = the coverage
// factor, 2 by default).

#include <QWidget>
#include <optional>

#include "core/iso/Iso230_2.h"

class QCustomPlot;
class QCPPainter;

namespace driftlab::ui {

class Iso230_2Plot : public QWidget {
    Q_OBJECT
public:
    explicit Iso230_2Plot(QWidget* parent = nullptr);

    /// With `accuracyTolerance_um`, two dashed lines T apart centred on the
    /// span of x̄ ± k·s: A is within its tolerance when the band fits between them.
    void show(const iso::Evaluation& evaluation,
              std::optional<double> accuracyTolerance_um = std::nullopt);
    void clear();
    int graphCount() const;
    /// Draws the figure shown into `painter` at width × height (a PDF page
    /// of the acceptance report draws it as vectors).
    void render(QCPPainter* painter, int width, int height);

private:
    QCustomPlot* m_plot;
};

}  // namespace driftlab::ui
