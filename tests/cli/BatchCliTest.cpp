// driftlab-cli batch (issue 14): a lab folder of bundles, a zipped bundle, a
// store with two campaigns and a corrupt bundle analysed at once, each item in
// its own process; every result equal to what the single command prints, the
// corrupt bundle reported with the reader's file:line:column reason, a hanging
// item stopped by the time limit, the same lines whatever -j.
#include <gtest/gtest.h>

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <memory>

#include "tests/db/StoreTestSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

QJsonObject json(const QByteArray& text) {
    return QJsonDocument::fromJson(text).object();
}

/// The JSON lines of a batch's stdout; fails the test on a line that is not an object.
QList<QJsonObject> jsonLines(const QByteArray& out) {
    QList<QJsonObject> lines;
    for (const QByteArray& line : out.split('\n')) {
        if (line.isEmpty()) continue;
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(line, &error);
        EXPECT_TRUE(doc.isObject())
            << error.errorString().toStdString() << ": " << line.constData();
        lines << doc.object();
    }
    return lines;
}

QStringList items(const QList<QJsonObject>& lines) {
    QStringList names;
    for (const QJsonObject& line : lines) names << line[QStringLiteral("item")].toString();
    return names;
}

/// The lines without the one key that differs between runs.
QList<QJsonObject> withoutSeconds(QList<QJsonObject> lines) {
    for (QJsonObject& line : lines) {
        EXPECT_GE(line[QStringLiteral("seconds")].toDouble(-1), 0);
        line.remove(QStringLiteral("seconds"));
    }
    return lines;
}

/// `fit --json` without how long the fit took, as batch reports it.
QJsonObject withoutTiming(QJsonObject fit) {
    QJsonObject inner = fit[QStringLiteral("fit")].toObject();
    QJsonObject metrics = inner[QStringLiteral("metrics")].toObject();
    EXPECT_TRUE(inner.contains(QStringLiteral("message")));
    EXPECT_TRUE(metrics.contains(QStringLiteral("identification_s")));
    metrics.remove(QStringLiteral("identification_s"));
    inner[QStringLiteral("metrics")] = metrics;
    inner.remove(QStringLiteral("message"));
    fit[QStringLiteral("fit")] = inner;
    return fit;
}

void simulate(const QString& out, const QString& runs, int seed) {
    const CliResult r =
        runCli({QStringLiteral("simulate"), QStringLiteral("--out"), out, QStringLiteral("--runs"),
                runs, QStringLiteral("--seed"), QString::number(seed)});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
}

}  // namespace

// The fixture is outside the anonymous namespace: its tests derive from it.
/// The lab folder every test reads, made once: two bundles (two moving
/// states, and one state so that it has a default ISO 230-2 run), a zip of
/// the first, a store with both imported and a bundle whose samples.csv was
/// cut off in the middle of a row.
class BatchCli : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = std::make_unique<QTemporaryDir>();
        const QDir lab(s_dir->filePath(QStringLiteral("lab")));
        QDir().mkpath(lab.path());
        simulate(lab.filePath(QStringLiteral("a")), QStringLiteral("S1,S3"), 1);
        simulate(lab.filePath(QStringLiteral("b")), QStringLiteral("S2"), 2);
        runTool(QStringLiteral("zip"),
                {QStringLiteral("-qr"), lab.filePath(QStringLiteral("c.zip")), QStringLiteral(".")},
                lab.filePath(QStringLiteral("a")));
        for (const char* bundle : {"a", "b"}) {
            const CliResult r =
                runCli({QStringLiteral("import"), lab.filePath(QLatin1String(bundle)),
                        QStringLiteral("--db"), lab.filePath(QStringLiteral("store.sqlite"))});
            ASSERT_EQ(r.exitCode, 0) << r.err.constData();
        }
        const QString broken = lab.filePath(QStringLiteral("broken"));
        copyBundle(lab.filePath(QStringLiteral("a")), broken);
        const QString samples = broken + QStringLiteral("/samples.csv");
        const QByteArray text = readFile(samples);
        // Cut in the middle of row 57: a file copy or download that stopped short.
        qsizetype at = 0;
        for (int line = 1; line < 57; ++line) at = text.indexOf('\n', at) + 1;
        writeFile(samples, text.left(at + 12));
    }
    static void TearDownTestSuite() { s_dir.reset(); }

    static QString lab(const QString& name = {}) {
        const QString path = s_dir->filePath(QStringLiteral("lab"));
        return name.isEmpty() ? path : path + QLatin1Char('/') + name;
    }

    static std::unique_ptr<QTemporaryDir> s_dir;
};

std::unique_ptr<QTemporaryDir> BatchCli::s_dir;

TEST_F(BatchCli, folderGivesEveryItemItsLineInInputOrderWithTheSingleCommandsResults) {
    const CliResult r =
        runCli({QStringLiteral("batch"), lab(), QStringLiteral("-j"), QStringLiteral("2"),
                QStringLiteral("--what"), QStringLiteral("info,iso230-2,fit")});
    EXPECT_EQ(r.exitCode, 1) << r.err.constData();
    EXPECT_EQ(reason(r.err), "driftlab-cli batch: 1 of 6 items failed (their lines say why)");
    EXPECT_TRUE(r.err.contains("batch: 6 of 6 done, 1 failed\n")) << r.err.constData();
    const QList<QJsonObject> lines = jsonLines(r.out);
    // A folder's finds in path order; each campaign of the store is FILE#ID.
    ASSERT_EQ(items(lines), QStringList({lab("a"), lab("b"), lab("broken"), lab("c.zip"),
                                         lab("store.sqlite") + "#1", lab("store.sqlite") + "#2"}));

    // The corrupt bundle: the reader's own reason, as `info` gives it.
    const QJsonObject broken = lines[2];
    EXPECT_FALSE(broken[QStringLiteral("ok")].toBool());
    const CliResult info = runCli({QStringLiteral("info"), lab("broken")});
    ASSERT_EQ(info.exitCode, 1);
    const QString reader = QString::fromUtf8(reason(info.err)).remove("driftlab-cli info: ");
    EXPECT_TRUE(reader.startsWith(lab("broken") + "/samples.csv:57:")) << qPrintable(reader);
    EXPECT_EQ(broken[QStringLiteral("error")].toString(), reader);

    // The good ones: what info, iso230-2 and fit print with --json.
    for (int i : {0, 1, 3, 4, 5}) {
        const QJsonObject& line = lines[i];
        EXPECT_TRUE(line[QStringLiteral("ok")].toBool()) << qPrintable(items(lines)[i]);
        EXPECT_FALSE(line.contains(QStringLiteral("error")));
        EXPECT_GE(line[QStringLiteral("seconds")].toDouble(-1), 0);
    }
    for (const QString& bundle : {QStringLiteral("a"), QStringLiteral("b")}) {
        const QJsonObject line = lines[bundle == QLatin1String("a") ? 0 : 1];
        const QJsonObject single =
            json(runCli({QStringLiteral("info"), lab(bundle), QStringLiteral("--json")}).out);
        for (const char* key : {"name", "machine", "axis", "runs", "channels"})
            EXPECT_EQ(line[QLatin1String(key)], single[QLatin1String(key)]) << key;
        const CliResult fit = runCli({QStringLiteral("fit"), lab(bundle), QStringLiteral("--model"),
                                      QStringLiteral("heat-transfer"), QStringLiteral("--json")});
        ASSERT_EQ(fit.exitCode, 0) << fit.err.constData();
        EXPECT_EQ(line[QStringLiteral("fit")].toObject(), withoutTiming(json(fit.out)));
    }
    // Two moving states: trained on the first, scored on the other.
    const QJsonObject fitA = lines[0][QStringLiteral("fit")].toObject();
    EXPECT_EQ(fitA[QStringLiteral("train_runs")].toArray(), QJsonArray({"S1"}));
    EXPECT_EQ(fitA[QStringLiteral("test_runs")].toArray(), QJsonArray({"S3"}));
    EXPECT_GT(fitA[QStringLiteral("test")][QStringLiteral("rms_um")].toDouble(), 0);
    // Neither run of a is the campaign's one positioning run; b's one run is.
    EXPECT_TRUE(lines[0][QStringLiteral("iso230_2")].isNull());
    EXPECT_FALSE(
        lines[0][QStringLiteral("skipped")][QStringLiteral("iso230_2")].toString().isEmpty());
    const QJsonObject iso =
        json(runCli({QStringLiteral("iso230-2"), lab("b"), QStringLiteral("--json")}).out);
    const QJsonObject isoB = lines[1][QStringLiteral("iso230_2")].toObject();
    EXPECT_EQ(isoB[QStringLiteral("run")].toString(), QStringLiteral("S2"));
    for (const char* key : {"A", "B", "E", "M", "R", "A_up", "R_down", "cycles", "edition"})
        EXPECT_EQ(isoB[QLatin1String(key)], iso[QLatin1String(key)]) << key;
    EXPECT_GT(isoB[QStringLiteral("A")].toDouble(), 0);

    // The zip is bundle a, the store's campaigns are a and b: the same results.
    auto results = [](QJsonObject line) {
        for (const char* key : {"item", "seconds"}) line.remove(QLatin1String(key));
        return line;
    };
    EXPECT_EQ(results(lines[3]), results(lines[0]));
    EXPECT_EQ(results(lines[4]), results(lines[0]));
    EXPECT_EQ(results(lines[5]), results(lines[1]));
}

TEST_F(BatchCli, oneOrTwoAtATimeGiveTheSameLines) {
    const QStringList args{
        QStringLiteral("batch"),   lab("b"), lab("broken"), lab("a"), QStringLiteral("--what"),
        QStringLiteral("info,fit")};
    const CliResult one = runCli(QStringList(args) << QStringLiteral("-j1"));
    const CliResult two = runCli(QStringList(args) << QStringLiteral("-j2"));
    EXPECT_EQ(one.exitCode, 1);
    EXPECT_EQ(two.exitCode, 1);
    EXPECT_TRUE(one.err.contains("batch: 3 items, 1 at a time\n")) << one.err.constData();
    EXPECT_TRUE(two.err.contains("batch: 3 items, 2 at a time\n")) << two.err.constData();
    const QList<QJsonObject> lines = withoutSeconds(jsonLines(one.out));
    ASSERT_EQ(items(lines), QStringList({lab("b"), lab("broken"), lab("a")}));
    EXPECT_EQ(withoutSeconds(jsonLines(two.out)), lines);
    // Not asked for, not there.
    EXPECT_FALSE(lines[0].contains(QStringLiteral("iso230_2")));
    EXPECT_FALSE(lines[0].contains(QStringLiteral("diagnosis")));
    EXPECT_TRUE(lines[0].contains(QStringLiteral("fit")));
}

TEST_F(BatchCli, diagnosisIsTheDiagnoseCommandsInShort) {
    const CliResult r = runCli({QStringLiteral("batch"), lab("store.sqlite") + "#1",
                                QStringLiteral("--what"), QStringLiteral("diagnose")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QList<QJsonObject> lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 1);
    EXPECT_EQ(lines[0][QStringLiteral("item")].toString(), lab("store.sqlite") + "#1");
    EXPECT_TRUE(lines[0][QStringLiteral("ok")].toBool());
    const QJsonObject d = lines[0][QStringLiteral("diagnosis")].toObject();

    const CliResult single =
        runCli({QStringLiteral("diagnose"), lab("a"), QStringLiteral("--json")});
    ASSERT_EQ(single.exitCode, 0) << single.err.constData();
    const QJsonObject full = json(single.out);
    EXPECT_FALSE(d[QStringLiteral("verdict")].toString().isEmpty());
    for (const char* key : {"verdict", "train_runs", "test_runs"})
        EXPECT_EQ(d[QLatin1String(key)], full[QLatin1String(key)]) << key;
    EXPECT_EQ(d[QStringLiteral("base")][QStringLiteral("test_rms_um")],
              full[QStringLiteral("base")][QStringLiteral("test_rms_um")]);
    const QJsonArray findings = d[QStringLiteral("findings")].toArray();
    const QJsonArray fullFindings = full[QStringLiteral("findings")].toArray();
    ASSERT_EQ(findings.size(), fullFindings.size());
    ASSERT_FALSE(findings.isEmpty());
    for (int i = 0; i < findings.size(); ++i) {
        EXPECT_EQ(findings[i][QStringLiteral("cause")], fullFindings[i][QStringLiteral("cause")]);
        EXPECT_EQ(findings[i][QStringLiteral("reduction")],
                  fullFindings[i][QStringLiteral("gain")][QStringLiteral("reduction")]);
    }
}

TEST_F(BatchCli, hangingItemIsStoppedByTheTimeLimitAndAMissingPathFailsAlone) {
    // A store another process keeps locked, readers too: its reader waits
    // for the lock (5 s, SQLite's busy timeout), longer than the time limit.
    QTemporaryDir dir;
    const QString store = dir.filePath(QStringLiteral("held.sqlite"));
    ASSERT_TRUE(QFile::copy(lab("store.sqlite"), store));
    const HeldStoreLock held(store, QStringLiteral("BEGIN EXCLUSIVE"));
    ASSERT_TRUE(held.locked);
    const QString hanging = store + QStringLiteral("#1");
    const QString missing = dir.filePath(QStringLiteral("no-such-bundle"));
    const CliResult r =
        runCli({QStringLiteral("batch"), hanging, missing, lab("b"), QStringLiteral("--what"),
                QStringLiteral("info"), QStringLiteral("--timeout-s"), QStringLiteral("3")});
    EXPECT_EQ(r.exitCode, 1);
    const QList<QJsonObject> lines = jsonLines(r.out);
    ASSERT_EQ(items(lines), QStringList({hanging, missing, lab("b")}));
    EXPECT_FALSE(lines[0][QStringLiteral("ok")].toBool());
    EXPECT_EQ(lines[0][QStringLiteral("error")].toString(),
              QStringLiteral("stopped after 3 s (--timeout-s)"));
    EXPECT_FALSE(lines[1][QStringLiteral("ok")].toBool());
    EXPECT_EQ(lines[1][QStringLiteral("error")].toString(), missing + ": no such file or folder");
    EXPECT_TRUE(lines[2][QStringLiteral("ok")].toBool());
    EXPECT_EQ(reason(r.err), "driftlab-cli batch: 2 of 3 items failed (their lines say why)");
}

TEST_F(BatchCli, allGoodExitsZeroAndUsageErrorsExitTwo) {
    const CliResult good = runCli(
        {QStringLiteral("batch"), lab("b"), QStringLiteral("--what"), QStringLiteral("info")});
    EXPECT_EQ(good.exitCode, 0) << good.err.constData();
    EXPECT_EQ(jsonLines(good.out).size(), 1);
    const QList<std::pair<QStringList, QByteArray>> refused{
        {{QStringLiteral("batch")}, "driftlab-cli batch: give at least one PATH"},
        {{QStringLiteral("batch"), lab("b"), QStringLiteral("--what"), QStringLiteral("info,plot")},
         "driftlab-cli batch: --what: 'plot' is not an analysis (info, iso230-2, fit, diagnose)"},
        {{QStringLiteral("batch"), lab("b"), QStringLiteral("-j"), QStringLiteral("0")},
         "driftlab-cli batch: -j: '0' is not a whole number of at least 1"}};
    for (const auto& [args, why] : refused) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 2) << qPrintable(args.join(' '));
        EXPECT_EQ(r.out, QByteArray());
        EXPECT_EQ(reason(r.err), why);
    }
    // The per-item child is DriftLab's own, not a command for users.
    EXPECT_FALSE(runCli({QStringLiteral("--help")}).out.contains("batch-item"));
}

TEST_F(BatchCli, memoryLimitReachesTheItemsProcessAndItsFailureIsItsLine) {
    // 64 MiB of address space is too little for the analysis process even to
    // load its libraries: the item fails with the reason its process gave.
    const CliResult r =
        runCli({QStringLiteral("batch"), lab("b"), QStringLiteral("--what"), QStringLiteral("info"),
                QStringLiteral("--memory-mb"), QStringLiteral("64")});
    EXPECT_EQ(r.exitCode, 1);
    const QList<QJsonObject> lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 1);
    EXPECT_FALSE(lines[0][QStringLiteral("ok")].toBool());
    EXPECT_FALSE(lines[0][QStringLiteral("error")].toString().isEmpty());
    EXPECT_FALSE(lines[0].contains(QStringLiteral("name")));
}
