#include "core/models/ModelFactory.h"

#include <functional>
#include <utility>
#include <vector>

#include "core/models/AllRisesHeatModel.h"
#include "core/models/AllRisesLagModel.h"
#include "core/models/AutoModel.h"
#include "core/models/ExponentialModel.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/LaggedSensorsModel.h"
#include "core/models/MlrModel.h"
#include "core/models/NoCompensationModel.h"
#include "core/models/PolyPositionModel.h"
#include "core/models/PrincipalRisesHeatModel.h"
#include "core/models/RidgeHeatModel.h"
#include "core/models/SensorlessModel.h"

namespace driftlab::models {
namespace {

using Maker = std::function<std::unique_ptr<ThermalErrorModel>()>;

/// Every model, once. A new model is one more line.
const std::vector<std::pair<QString, Maker>>& registry() {
    static const std::vector<std::pair<QString, Maker>> models{
        {QStringLiteral("mlr"), [] { return std::make_unique<MlrModel>(); }},
        {QStringLiteral("poly-position"), [] { return std::make_unique<PolyPositionModel>(); }},
        {QStringLiteral("exponential"), [] { return std::make_unique<ExponentialModel>(); }},
        {QStringLiteral("heat-transfer"), [] { return std::make_unique<HeatTransferModel>(); }},
        {QStringLiteral("sensorless"), [] { return std::make_unique<SensorlessModel>(); }},
        {QStringLiteral("arx"), [] { return std::make_unique<LaggedSensorsModel>(); }},
        {QStringLiteral("arx-all"), [] { return std::make_unique<AllRisesLagModel>(); }},
        {QStringLiteral("lsall-heat"), [] { return std::make_unique<AllRisesHeatModel>(); }},
        {QStringLiteral("ridge-heat"), [] { return std::make_unique<RidgeHeatModel>(); }},
        {QStringLiteral("pcr-heat"), [] { return std::make_unique<PrincipalRisesHeatModel>(); }},
    };
    return models;
}

}  // namespace

QStringList modelNames() {
    QStringList names;
    for (const auto& [name, make] : registry()) names << name;
    return names;
}

QStringList modelNamesFor(const QString& target) {
    QStringList names = modelNames();
    if (!target.isEmpty()) {
        names.removeAll(QStringLiteral("heat-transfer"));
    } else {
        for (const char* drift : {"lsall-heat", "ridge-heat", "pcr-heat"})
            names.removeAll(QString::fromLatin1(drift));
    }
    return names;
}

QStringList fitModelNames() {
    return modelNames() << QStringLiteral("auto") << QStringLiteral("none");
}

std::unique_ptr<ThermalErrorModel> makeModel(const QString& name) {
    if (name == QLatin1String("auto")) return std::make_unique<AutoModel>();
    if (name == QLatin1String("none")) return std::make_unique<NoCompensationModel>();
    for (const auto& [known, make] : registry())
        if (known == name) return make();
    return nullptr;
}

}  // namespace driftlab::models
