#pragma once
// The kind-specific object of a procedure file, read (with its checks) and
// written. Internal to Procedure.cpp; readers throw ProcedureError.

#include <QJsonObject>
#include <QString>

#include "core/procedures/Procedure.h"

namespace driftlab::procedures {

PositioningSpec readPositioning(const QJsonObject& json, const QString& path,
                                const RangeMm& travel_mm);
ThermalDistortionSpec readThermalDistortion(const QJsonObject& json, const QString& path,
                                            const RangeMm& travel_mm);
EtveSpec readEtve(const QJsonObject& json, const QString& path);
SpindleSpec readSpindle(const QJsonObject& json, const QString& path);
MovingStatesSpec readMovingStates(const QJsonObject& json, const QString& path,
                                  const RangeMm& travel_mm);

QJsonObject toJson(const PositioningSpec& spec);
QJsonObject toJson(const ThermalDistortionSpec& spec);
QJsonObject toJson(const EtveSpec& spec);
QJsonObject toJson(const SpindleSpec& spec);
QJsonObject toJson(const MovingStatesSpec& spec);

}  // namespace driftlab::procedures
