#pragma once
// An adopted extension as a model of its own: the heat-transfer model with
// the causes a diagnosis named ("heat-transfer+motor_heat"), refitted on any
// training runs. What live compensation steps online when the user chose the
// extension over the base model; only effects on the screw's heat flow can
// run there, since live compensation predicts the screw, not a sensor.

#include <QStringList>

#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

class ExtendedHeatTransferModel final : public models::HeatTransferModel {
public:
    /// `causes` in the order the diagnosis adopted them.
    explicit ExtendedHeatTransferModel(QStringList causes);
    /// "heat-transfer+motor_heat", as the adopted fit is stored.
    QString name() const override;

    /// The causes of `model` ("heat-transfer+A+B"), or empty with `why`
    /// when it does not name an extension of heat-transfer.
    static QStringList causesOf(const QString& model, QString* why);

protected:
    /// The base fit first: its residuals give the effects their starting
    /// time constants, its values the extension's start. Throws ModelError
    /// naming the cause the runs cannot support, or one that acts on the
    /// readings only.
    models::FitSummary fitRuns(const std::vector<models::RunData>& training) override;

private:
    QStringList m_causes;
};

}  // namespace driftlab::diagnosis
