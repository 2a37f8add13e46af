#pragma once
// Shared by the engine tests and the Run page tests: a short simulated
// procedure, and the run statuses of a store as logged.
#include <QSqlQuery>
#include <QStringList>

#include "core/procedures/Procedure.h"
#include "db/CampaignStore.h"

namespace driftlab::test {

/// Two short moving states (50 min and 30 min of run time).
inline procedures::Procedure twoShortMovingStates() {
    procedures::Procedure p;
    p.name = QStringLiteral("two short moving states");
    p.kind = procedures::ProcedureKind::MovingStates;
    procedures::MovingStatesSpec m;
    m.states = {{QStringLiteral("S1"), 8000, {210, 490}, 1800, 1200},
                {QStringLiteral("S2"), 4000, {70, 630}, 1200, 600}};
    p.moving_states = m;
    return p;
}

/// "NAME=STATUS" per run of the store, in logging order (read-only).
inline QStringList runStatuses(const QString& path) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    QStringList out;
    if (!store) return out;
    QSqlQuery q(store->database());
    q.exec(QStringLiteral("SELECT name || '=' || status FROM run ORDER BY id"));
    while (q.next()) out << q.value(0).toString();
    return out;
}

}  // namespace driftlab::test
