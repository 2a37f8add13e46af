#pragma once
// What the GUI tests share: a store made with the real CLI, a channel of the
// set-up tables, and waiting for a signal. The QApplication is made by the
// tests' main (tests/support/QtTestMain.cpp).
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTemporaryDir>

#include "core/domain/Channel.h"
#include "tests/support/CliRunner.h"
#include "tests/support/SignalWait.h"

namespace driftlab::test {

/// The example campaign (resources/examples/x-axis-moving-state, run S1 with
/// positioning readings) imported with `driftlab-cli import` into dir/store.sqlite.
inline QString importExample(const QTemporaryDir& dir, qint64* campaignId) {
    const CliResult r =
        runCli({QStringLiteral("import"),
                QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state"),
                QStringLiteral("--db"), dir.filePath(QStringLiteral("store.sqlite"))});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    *campaignId = r.out.trimmed().toLongLong();
    return dir.filePath(QStringLiteral("store.sqlite"));
}

/// A channel of the setup tables: its id, quantity and role.
inline Channel channel(const char* id, Quantity quantity, ChannelRole role) {
    Channel c;
    c.id = QString::fromLatin1(id);
    c.quantity = quantity;
    c.role = role;
    return c;
}

}  // namespace driftlab::test
