#include "tests/cli/RealWorldBundleSupport.h"

#include <gtest/gtest.h>
#include <QFileInfo>
#include <QProcess>

#include "core/bundle/BundleReader.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

namespace driftlab::test {

/// Imports `bundle` into a new store and exports it again: what DriftLab stored.
Campaign importedAndExported(const QString& bundle, const QDir& work, QByteArray* err) {
    const QString db = work.filePath(QStringLiteral("lab.sqlite"));
    QFile::remove(db);
    CliResult imported = runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), db});
    EXPECT_EQ(imported.exitCode, 0) << imported.err.constData();
    if (err) *err = imported.err;
    const QString out = work.filePath(QStringLiteral("exported"));
    QDir(out).removeRecursively();
    CliResult exported =
        runCli({QStringLiteral("export"), QStringLiteral("--db"), db, QStringLiteral("--campaign"),
                imported.out.trimmed(), QStringLiteral("--out"), out});
    EXPECT_EQ(exported.exitCode, 0) << exported.err.constData();
    bundle::BundleReadResult back = bundle::readBundle(out);
    EXPECT_TRUE(back.ok());
    return back.ok() ? *back.campaign : Campaign{};
}

/// Rewrites `bundle` with a Python script (given the folder) as other software
/// would write it; imported and exported, it must be the plain example, and
/// the import must warn `warning`.
void expectRewrittenImportsAsThePlainBundle(const QString& bundle, const char* script,
                                            const char* warning) {
    runTool(QStringLiteral(DRIFTLAB_PYTHON),
            {QStringLiteral("-c"), QString::fromUtf8(script), bundle});
    QByteArray err;
    EXPECT_EQ(importedAndExported(bundle, QFileInfo(bundle).dir(), &err), exampleCampaign());
    if (warning)
        EXPECT_TRUE(err.contains(warning)) << err.constData();
    else
        EXPECT_FALSE(err.contains("warning")) << err.constData();
}

}  // namespace driftlab::test
