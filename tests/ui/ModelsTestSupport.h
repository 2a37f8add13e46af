#pragma once
// Shared by the Models and Diagnosis page tests: stores made by the real CLI (simulate + import),
// and waiting for a page's background job.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "db/ModelFitStore.h"
#include "tests/support/CliRunner.h"
#include "ui/shell/BackgroundJob.h"

namespace driftlab::test {

/// A simulated campaign imported into a new store; returns the store path
/// (made once per argument set, then copied so each test writes its own).
inline QString simulatedStore(const QTemporaryDir& dir, const QStringList& simulateArgs,
                              const QString& name) {
    static std::map<QStringList, QString> made;
    static QTemporaryDir cache;
    auto found = made.find(simulateArgs);
    if (found == made.end()) {
        const QString bundle = cache.filePath(QStringLiteral("b%1").arg(made.size()));
        const QString db = cache.filePath(QStringLiteral("s%1.db").arg(made.size()));
        const CliResult sim =
            runCli(QStringList{QStringLiteral("simulate"), QStringLiteral("--out"), bundle} +
                   simulateArgs);
        EXPECT_EQ(sim.exitCode, 0) << sim.err.constData();
        const CliResult imp =
            runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), db});
        EXPECT_EQ(imp.exitCode, 0) << imp.err.constData();
        found = made.emplace(simulateArgs, db).first;
    }
    const QString path = dir.filePath(name);
    EXPECT_TRUE(QFile::copy(found->second, path));
    return path;
}

/// Waits (processing events) until the job has ended; false after 5 minutes.
inline bool waitForJob(const ui::BackgroundJob& job) {
    return QTest::qWaitFor([&] { return !job.isRunning(); }, 300'000);
}

inline std::size_t storedFits(const QString& path) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    return store ? db::modelFits(*store, 1).size() : 0;
}

}  // namespace driftlab::test
