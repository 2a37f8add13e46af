#pragma once
// The diagnosis as pictures: the positioning residual of the base model over
// position × time, and the thermal error at the far target before and after
// the adopted extension. PNG through QCustomPlot offscreen; the GUI and the
// report reuse them.

#include <QString>

#include "core/models/HeatTransferModel.h"
#include "ui/plots/PngPlots.h"

namespace driftlab::ui {

/// Residual map of one run: targets × passes, the two directions averaged.
MapPlot residualMapPlot(const models::ReadingResiduals& residuals, const QString& title);
/// Measured thermal error at the farthest target against time, with the base
/// model's prediction and (when given) the adopted extension's.
CurvePlot beforeAfterPlot(const models::RunData& run, const models::ReadingResiduals& base,
                          const models::ReadingResiduals* adopted, const QString& adoptedName,
                          const QString& title);

/// Residual map of one run: targets × passes, the two directions averaged.
bool saveResidualMap(const models::ReadingResiduals& residuals, const QString& path,
                     const QString& title, QString* error);

/// Measured thermal error at the farthest target against time, with the base
/// model's prediction and (when given) the adopted extension's.
bool saveBeforeAfter(const models::RunData& run, const models::ReadingResiduals& base,
                     const models::ReadingResiduals* adopted, const QString& adoptedName,
                     const QString& path, const QString& title, QString* error);

}  // namespace driftlab::ui
