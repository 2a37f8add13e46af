// No harm, as a test engineer meets it: on a campaign whose thermal error is
// pure noise (the sensors warm and cool, the axis does not drift), `auto`
// chooses no compensation and says so, a single model that fits the noise is
// reported as worse than none, and `compensate` refuses to put either into a
// table unless --force overrides it.

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>

#include "tests/cli/RealWorldBundleSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"
#include "tests/support/PureNoise.h"

using namespace driftlab::test;

namespace {

/// A simulated four-state campaign whose every reading after cycle 0 is its
/// cycle-0 reading plus white noise of 1 µm: no thermal error at all.
const QString& noiseBundle() {
    static QTemporaryDir dir;
    static const QString path = [] {
        const QString bundle = dir.filePath(QStringLiteral("noise"));
        copyBundle(simulatedCampaign(QStringLiteral("S1,S2,S3,S4"), 5), bundle);
        replaceDriftByNoise(bundle);
        return bundle;
    }();
    return path;
}

CliResult fit(const QString& model, QStringList more = {}) {
    return runCli(QStringList{QStringLiteral("fit"), noiseBundle(), QStringLiteral("--model"),
                              model, QStringLiteral("--train"), QStringLiteral("S1,S2,S3"),
                              QStringLiteral("--test"), QStringLiteral("S4")} +
                  more);
}

CliResult compensate(const QString& out, const QString& model, QStringList more = {}) {
    return runCli(QStringList{QStringLiteral("compensate"), noiseBundle(), QStringLiteral("--run"),
                              QStringLiteral("S4"), QStringLiteral("--format"),
                              QStringLiteral("csv"), QStringLiteral("--out"), out,
                              QStringLiteral("--model"), model, QStringLiteral("--train"),
                              QStringLiteral("S1,S2,S3"), QStringLiteral("--at"),
                              QStringLiteral("S4@3600")} +
                  more);
}

}  // namespace

TEST(NoHarmCli, autoChoosesNoCompensationOnPureNoiseAndSaysSo) {
    const CliResult r = fit(QStringLiteral("auto"), {QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject fitted = json(r);
    const QJsonArray notes = fitted["fit"].toObject()["notes"].toArray();
    ASSERT_FALSE(notes.isEmpty());
    EXPECT_TRUE(notes.first().toString().startsWith(
        QStringLiteral("auto chose no compensation: no model family does better than none")))
        << qPrintable(notes.first().toString());
    // It predicts nothing, so it removes nothing and does no harm.
    EXPECT_DOUBLE_EQ(fitted["test"].toObject()["reduction"].toDouble(), 0);
    EXPECT_FALSE(fitted["test"].toObject()["worse_than_none"].toBool());
    EXPECT_FALSE(fitted["validation"].toObject()["worse_than_none"].toBool());
}

TEST(NoHarmCli, aModelThatFitsTheNoiseIsWorseThanNoneAndTheTextSaysItAsAnError) {
    const CliResult r = fit(QStringLiteral("mlr"));
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.out.contains("note: worse than no compensation where it was not fitted"))
        << r.out.constData();
    EXPECT_TRUE(
        r.out.contains("\nerror: the model makes the held-out runs' thermal error worse, "
                       "not better"))
        << r.out.constData();
    const CliResult j = fit(QStringLiteral("mlr"), {QStringLiteral("--json")});
    EXPECT_TRUE(json(j)["test"].toObject()["worse_than_none"].toBool());
    EXPECT_TRUE(json(j)["validation"].toObject()["worse_than_none"].toBool());
}

TEST(NoHarmCli, compensateRefusesAModelWorseThanNoneUnlessForced) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("x.csv"));
    CliResult r = compensate(out, QStringLiteral("mlr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(
        reason(r.err).contains("--model mlr does worse than no compensation where it was "
                               "not fitted"))
        << r.err.constData();
    EXPECT_TRUE(reason(r.err).endsWith("--force overrides")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(out));
    r = compensate(out, QStringLiteral("mlr"), {QStringLiteral("--force")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.err.contains("(used anyway: --force)")) << r.err.constData();
    EXPECT_TRUE(QFile::exists(out));
}

TEST(NoHarmCli, compensateRefusesAThermalPartAutoDeclined) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("x.csv"));
    const CliResult r = compensate(out, QStringLiteral("auto"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).contains("auto chose no compensation")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(out));
}
