#include "acquisition/push/PushResult.h"

#include <QJsonArray>

namespace driftlab::push {

QString outcomeName(PushOutcome outcome) {
    switch (outcome) {
        case PushOutcome::Applied:
            return QStringLiteral("applied");
        case PushOutcome::RolledBack:
            return QStringLiteral("rolled_back");
        case PushOutcome::Refused:
            return QStringLiteral("refused");
        case PushOutcome::Failed:
            return QStringLiteral("failed");
    }
    return QStringLiteral("failed");
}

QJsonObject PushResult::toJson() const {
    QJsonArray stepList;
    for (const PushStep& step : steps)
        stepList.append(QJsonObject{{QStringLiteral("step"), step.name},
                                    {QStringLiteral("ok"), step.ok},
                                    {QStringLiteral("detail"), step.detail}});
    return {{QStringLiteral("result"), outcomeName(outcome)},
            {QStringLiteral("message"), message},
            {QStringLiteral("controller"), controller},
            {QStringLiteral("version"), int(version)},
            {QStringLiteral("active_before"), int(active_before)},
            {QStringLiteral("points"), points},
            {QStringLiteral("checksum"), int(checksum)},
            {QStringLiteral("capacity"), capacity},
            {QStringLiteral("previous_intact"),
             previous_intact ? QJsonValue(*previous_intact) : QJsonValue()},
            {QStringLiteral("write_requests"), write_requests},
            {QStringLiteral("requests"), requests},
            {QStringLiteral("elapsed_s"), elapsed_s},
            {QStringLiteral("steps"), stepList}};
}

}  // namespace driftlab::push
