#pragma once
// Waiting for a signal in the tests that run an event loop.
#include <QSignalSpy>

namespace driftlab::test {

/// How long a test waits for a signal before it fails: generous, so that only
/// a hang fails, never a slow machine.
constexpr int kSignalWaitMs = 60'000;

/// Waits (event loop running) until `spy` has at least `count` signals.
inline bool waitFor(QSignalSpy& spy, int count = 1) {
    while (spy.count() < count)
        if (!spy.wait(kSignalWaitMs)) return spy.count() >= count;
    return true;
}

}  // namespace driftlab::test
