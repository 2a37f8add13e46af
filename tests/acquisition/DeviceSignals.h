#pragma once
// Waiting for a device worker's signals in the acquisition tests.
#include <QSignalSpy>

namespace driftlab::test {

/// How long a test waits for a device's signal before it fails.
constexpr int kEventWaitMs = 20'000;

/// Waits (bounded) until `spy` has at least `count` signals.
inline bool waitFor(QSignalSpy& spy, int count) {
    while (spy.count() < count)
        if (!spy.wait(kEventWaitMs)) return spy.count() >= count;
    return true;
}

}  // namespace driftlab::test
