#pragma once
// What the GUI tests share: one QApplication for the process (offscreen), a
// short simulated procedure, and the run statuses of a store as logged.

#include <QApplication>

#include "tests/acquisition/LoggedRunSupport.h"

namespace driftlab::uitest {

inline QApplication& app() {
    static int argc = 1;
    static char name[] = "ui_run_tests";
    static char* argv[] = {name, nullptr};
    static QApplication* instance = new QApplication(argc, argv);
    return *instance;
}

using test::runStatuses;
using test::twoShortMovingStates;

}  // namespace driftlab::uitest
