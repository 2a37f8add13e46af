#pragma once
// What the GUI tests share: one QApplication for the test binary (with
// QSettings redirected to a temporary folder, so no test touches the user's
// settings), a store made with the real CLI, and waiting for a signal.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "core/domain/Channel.h"
#include "tests/cli/CliRunner.h"

namespace driftlab::test {

inline QApplication& testApplication() {
    static int argc = 1;
    static char name[] = "ui_compensation_tests";
    static char* argv[] = {name, nullptr};
    static QTemporaryDir settingsDir;
    static QApplication* app = [] {
        QCoreApplication::setOrganizationName(QStringLiteral("DriftLabTests"));
        QCoreApplication::setApplicationName(QStringLiteral("ui_compensation_tests"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
        return new QApplication(argc, argv);
    }();
    return *app;
}

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

/// Waits (event loop running) until `spy` has at least `count` signals; a
/// generous bound only so that a hang fails instead of blocking the suite.
inline bool waitFor(QSignalSpy& spy, int count = 1) {
    while (spy.count() < count)
        if (!spy.wait(60'000)) return false;
    return true;
}

}  // namespace driftlab::test
