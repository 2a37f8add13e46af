// The ISO 230-3 page driven through its widgets on the example store: the
// moving run S1 and the spindle run SP1 show the figures of
// `driftlab-cli iso230-3 --json` on the same store and run, and an edited
// criterion (W, D) or probe distance changes them as the same options do.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <cmath>

#include "core/iso/Iso230_3Json.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/DriftSeriesModel.h"
#include "ui/pages/Iso230_3Page.h"
#include "ui/shell/Session.h"
#include "ui/widgets/Iso230_3Plot.h"

using namespace driftlab;
using namespace driftlab::test;
using DriftModel = ui::DriftSeriesModel;

/// The example campaign imported into a store and shown on the page.
class Iso230_3PageTest : public ::testing::Test {
protected:
    void SetUp() override {
        db = importExample(dir, &campaign);
        QString error;
        ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
        session.selectCampaign(campaign);
        ASSERT_TRUE(waitFor(evaluated));
    }

    /// The run's object of `iso230-3 --json` with `options`, without what the
    /// caller adds to core's JSON (run, kind, acceptance).
    QJsonObject cliRun(const QString& run, const QStringList& options = {}) {
        const CliResult r =
            runCli(QStringList{QStringLiteral("iso230-3"), QStringLiteral("--db"), db,
                               QStringLiteral("--campaign"), QString::number(campaign),
                               QStringLiteral("--run"), run, QStringLiteral("--json")} +
                   options);
        EXPECT_EQ(r.exitCode, 0) << r.err.constData();
        QJsonObject o = QJsonDocument::fromJson(r.out)
                            .object()
                            .value(QStringLiteral("runs"))
                            .toArray()
                            .at(0)
                            .toObject();
        EXPECT_EQ(o.value(QStringLiteral("run")).toString(), run);
        for (const char* key : {"run", "kind", "acceptance"}) o.remove(QLatin1String(key));
        return o;
    }

    /// The page's evaluation as JSON (empty when it has none).
    QJsonObject shown() const {
        return page.drift() ? iso::runDriftJson(*page.drift()) : QJsonObject();
    }

    /// Selects `run` in the page's run box and waits for its evaluation.
    void chooseRun(const QString& run) {
        const int index = page.runBox()->findData(run);
        ASSERT_GE(index, 0) << qPrintable(run);
        if (index == page.runBox()->currentIndex()) return;  // shown since SetUp
        evaluated.clear();
        page.runBox()->setCurrentIndex(index);
        ASSERT_TRUE(waitFor(evaluated));
    }

    /// Sets a criterion box and waits for the evaluation it starts.
    void edit(QDoubleSpinBox* box, double value) {
        evaluated.clear();
        box->setValue(value);
        ASSERT_TRUE(waitFor(evaluated));
    }

    /// The table's row `row` against the CLI's series object `cli`.
    void expectRow(int row, const QJsonObject& cli) const {
        const DriftModel& m = *page.seriesModel();
        const auto number = [&](int column) {
            return m.data(m.index(row, column), Qt::UserRole).toDouble();
        };
        EXPECT_NEAR(number(DriftModel::MaxDrift), cli[QStringLiteral("max_drift_um")].toDouble(),
                    1e-9);
        EXPECT_EQ(number(DriftModel::MaxDriftTime),
                  cli[QStringLiteral("max_drift_time_s")].toDouble());
        EXPECT_NEAR(number(DriftModel::Range), cli[QStringLiteral("range_um")].toDouble(), 1e-9);
        EXPECT_NEAR(number(DriftModel::Final), cli[QStringLiteral("final_drift_um")].toDouble(),
                    1e-9);
        const QJsonValue stabilised = cli[QStringLiteral("stabilised_time_s")];
        if (stabilised.isNull())
            EXPECT_TRUE(std::isnan(number(DriftModel::Stabilised)));
        else
            EXPECT_EQ(number(DriftModel::Stabilised), stabilised.toDouble());
    }

    QTemporaryDir dir;
    qint64 campaign = 0;
    QString db;
    ui::Session session;
    ui::Iso230_3Page page{session};
    QSignalSpy evaluated{&page, &ui::Iso230_3Page::evaluated};
};

TEST_F(Iso230_3PageTest, movingRunShowsTheCliFiguresAndFollowsTheCriterion) {
    ASSERT_EQ(page.runBox()->count(), 2);  // S1 (moving) and SP1 (spindle)
    chooseRun(QStringLiteral("S1"));
    ASSERT_TRUE(page.drift() && page.drift()->axis) << qPrintable(page.messageLabel()->text());
    const QJsonObject cli = cliRun(QStringLiteral("S1"));
    EXPECT_EQ(shown(), cli);
    const QJsonArray targets = cli[QStringLiteral("targets")].toArray();
    ASSERT_EQ(page.seriesModel()->rowCount(), targets.size());
    for (int row = 0; row < targets.size(); ++row) expectRow(row, targets[row].toObject());
    EXPECT_TRUE(page.summaryLabel()->text().contains(QStringLiteral("Max drift 30.110 µm")));
    EXPECT_TRUE(page.summaryLabel()->text().contains(QStringLiteral("not stabilised")));
    // A curve per target and direction; the map has a cell per target and cycle.
    EXPECT_EQ(page.plot()->seriesCount(), targets.size());
    ASSERT_TRUE(page.plot()->hasDriftMap());
    EXPECT_EQ(page.plot()->driftMapCells(),
              targets.size() / 2 * cli[QStringLiteral("cycles")].toInt());

    // A looser criterion: S1 stabilises, at the time `--tolerance-um 20 --window-s 300` gives.
    edit(page.toleranceBox(), 20);
    edit(page.windowBox(), 300);
    const QJsonObject loose =
        cliRun(QStringLiteral("S1"), {QStringLiteral("--tolerance-um"), QStringLiteral("20"),
                                      QStringLiteral("--window-s"), QStringLiteral("300")});
    ASSERT_FALSE(loose[QStringLiteral("stabilised_time_s")].isNull());
    EXPECT_EQ(shown(), loose);
    EXPECT_TRUE(page.summaryLabel()->text().contains(
        QStringLiteral("stabilised at %1 s")
            .arg(loose[QStringLiteral("stabilised_time_s")].toDouble())));
}

TEST_F(Iso230_3PageTest, spindleRunShowsTheProbesTiltsAndTemperaturesOfTheCli) {
    chooseRun(QStringLiteral("SP1"));
    ASSERT_TRUE(page.drift() && page.drift()->probes) << qPrintable(page.messageLabel()->text());
    const QJsonObject cli = cliRun(QStringLiteral("SP1"));
    EXPECT_EQ(shown(), cli);
    const QJsonArray probes = cli[QStringLiteral("probes")].toArray();
    ASSERT_EQ(probes.size(), 5);
    ASSERT_EQ(page.seriesModel()->rowCount(), 5);
    for (int row = 0; row < 5; ++row) expectRow(row, probes[row].toObject());
    EXPECT_EQ(page.plot()->seriesCount(), 5);
    EXPECT_FALSE(page.plot()->hasDriftMap());
    EXPECT_GT(page.plot()->temperatureCount(), 0);

    // The probe distance gives tilts A and B, as --probe-distance-mm does.
    edit(page.probeDistanceBox(), 250);
    const QJsonObject tilted = cliRun(
        QStringLiteral("SP1"), {QStringLiteral("--probe-distance-mm"), QStringLiteral("250")});
    ASSERT_EQ(tilted[QStringLiteral("tilts")].toArray().size(), 2);
    EXPECT_EQ(shown(), tilted);
    ASSERT_EQ(page.seriesModel()->rowCount(), 7);
    EXPECT_EQ(page.seriesModel()->columnCount(), DriftModel::MaxTilt + 1);
    EXPECT_EQ(page.plot()->seriesCount(), 7);

    // A criterion SP1 meets only late in the run: the time of the CLI's.
    edit(page.toleranceBox(), 3);
    edit(page.windowBox(), 300);
    const QJsonObject late =
        cliRun(QStringLiteral("SP1"), {QStringLiteral("--probe-distance-mm"), QStringLiteral("250"),
                                       QStringLiteral("--tolerance-um"), QStringLiteral("3"),
                                       QStringLiteral("--window-s"), QStringLiteral("300")});
    EXPECT_EQ(shown(), late);
}
