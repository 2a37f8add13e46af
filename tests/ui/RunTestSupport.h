#pragma once
// What the Run page tests share: a
// short simulated procedure, and the run statuses of a store as logged.

#include <QApplication>

#include "tests/acquisition/LoggedRunSupport.h"

namespace driftlab::uitest {

using test::runStatuses;
using test::twoShortMovingStates;

}  // namespace driftlab::uitest
