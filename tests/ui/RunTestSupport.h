#pragma once
// What the GUI tests share: one QApplication for the process (offscreen), a
// short simulated procedure, and the run statuses of a store as logged.

#include <QApplication>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStringList>
#include <QUuid>

#include "core/procedures/Procedure.h"

namespace driftlab::uitest {

inline QApplication& app() {
    static int argc = 1;
    static char name[] = "ui_run_tests";
    static char* argv[] = {name, nullptr};
    static QApplication* instance = new QApplication(argc, argv);
    return *instance;
}

/// Two short moving states (50 min and 30 min of run time, a row a second).
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

/// "NAME=STATUS" per run of the store, in logging order.
inline QStringList runStatuses(const QString& path, QStringList* sampleCounts = nullptr) {
    QStringList out;
    const QString name = QUuid::createUuid().toString();
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        db.open();
        QSqlQuery q(db);
        q.exec(QStringLiteral("SELECT name || '=' || status FROM run ORDER BY id"));
        while (q.next()) out << q.value(0).toString();
        Q_UNUSED(sampleCounts);
    }
    QSqlDatabase::removeDatabase(name);
    return out;
}

}  // namespace driftlab::uitest
