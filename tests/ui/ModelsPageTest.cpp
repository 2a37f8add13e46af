// The Models page through its widgets on stores made by the real CLI: a fit
// appears and is stored, Cancel stops a long job with nothing stored, and the
// cross-state matrix shows what `driftlab-cli compare --json` prints.
#include <QComboBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QPushButton>
#include <QTabWidget>
#include <cmath>

#include "ModelsTestSupport.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/ModelFactory.h"
#include "ui/models/CrossStateMatrixModel.h"
#include "ui/models/ModelParametersModel.h"
#include "ui/models/TestScoresModel.h"
#include "ui/pages/DiagnosisPage.h"
#include "ui/pages/ModelsPage.h"
#include "ui/shell/FitJob.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/FitSetupPanel.h"
#include "ui/widgets/PlotView.h"
#include "ui/widgets/PredictionPlotWidget.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QStringList kTwoRuns{QStringLiteral("--runs"), QStringLiteral("S1,S3")};
const QStringList kFiveRuns{};

/// A main window on `store`, campaign 1 selected, the Models tab shown, its
/// run lists read.
std::unique_ptr<ui::MainWindow> windowOn(const QString& store) {
    auto window = std::make_unique<ui::MainWindow>();
    EXPECT_TRUE(window->openStore(store, false, false));
    window->session().selectCampaign(1);
    window->pages()->setCurrentWidget(window->modelsPage());
    window->show();
    window->resize(1280, 800);  // the smallest window the GUI supports
    EXPECT_TRUE(waitForJob(*window->modelsPage()->job()));
    return window;
}

void choose(QComboBox* box, const QString& data) {
    const int index = box->findData(data);
    ASSERT_GE(index, 0) << data.toStdString();
    box->setCurrentIndex(index);
}

void check(QListWidget* list, const QStringList& runs) {
    for (int i = 0; i < list->count(); ++i)
        list->item(i)->setCheckState(runs.contains(list->item(i)->text()) ? Qt::Checked
                                                                          : Qt::Unchecked);
}

QJsonObject cliJson(const QStringList& args) {
    const CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out).object();
}

}  // namespace

TEST(ModelsPage, fitThroughTheWidgetsShowsStoresAndMatchesTheCli) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kTwoRuns, QStringLiteral("fit.db"));
    auto window = windowOn(store);
    ui::ModelsPage& page = *window->modelsPage();
    ASSERT_EQ(page.setupPanel()->trainList()->count(), 2);
    QStringList offered;
    for (int i = 0; i < page.setupPanel()->modelBox()->count(); ++i)
        offered << page.setupPanel()->modelBox()->itemText(i);
    EXPECT_EQ(offered, models::fitModelNames());
    choose(page.setupPanel()->modelBox(), QStringLiteral("mlr"));
    check(page.setupPanel()->trainList(), {QStringLiteral("S1")});
    check(page.setupPanel()->testList(), {QStringLiteral("S3")});
    ASSERT_TRUE(page.fitButton()->isEnabled());
    QTest::mouseClick(page.fitButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));

    EXPECT_TRUE(page.status().contains(QStringLiteral("stored as fit")))
        << page.status().toStdString();
    EXPECT_EQ(storedFits(store), 1u);
    EXPECT_GT(page.parametersModel()->rowCount(), 0);
    ASSERT_EQ(page.scoresModel()->rowCount(), 1);
    EXPECT_EQ(page.scoresModel()->index(0, ui::TestScoresModel::Run).data().toString(),
              QStringLiteral("S3"));
    // measured, model, residual, and the prediction interval above and below
    EXPECT_EQ(page.predictions()->plot()->curveCount(), 5);

    // The same fit by the CLI on a copy of the store made before: the same held-out score.
    const QString copy = simulatedStore(dir, kTwoRuns, QStringLiteral("cli.db"));
    const QJsonObject cli =
        cliJson({QStringLiteral("fit"), QStringLiteral("--db"), copy, QStringLiteral("--campaign"),
                 QStringLiteral("1"), QStringLiteral("--model"), QStringLiteral("mlr"),
                 QStringLiteral("--train"), QStringLiteral("S1"), QStringLiteral("--test"),
                 QStringLiteral("S3"), QStringLiteral("--json")});
    const double cliRms =
        cli[QStringLiteral("test")].toObject()[QStringLiteral("rms_um")].toDouble();
    EXPECT_EQ(page.scoresModel()->index(0, ui::TestScoresModel::Rms).data().toString(),
              QString::number(cliRms, 'f', 2));
    // S3 runs faster than S1: the notes say where its temperatures leave
    // S1's, beginning with the channel the CLI names first.
    const QJsonArray beyond = cli[QStringLiteral("beyond_training")].toArray();
    ASSERT_FALSE(beyond.isEmpty());
    const QString firstChannel = beyond.first().toObject()[QStringLiteral("channel")].toString();
    EXPECT_TRUE(page.notes().contains(
        QStringLiteral("<br>Beyond the training runs' temperature rises (the prediction "
                       "extrapolates there): S3: %1 (")
            .arg(firstChannel)))
        << page.notes().toStdString();
    // How sure the prediction is, as the CLI says it: the interval and its
    // coverage of S3.
    const QJsonObject coverage =
        cli[QStringLiteral("test")].toObject()[QStringLiteral("coverage")].toObject();
    const double halfWidth = cli[QStringLiteral("validation")]
                                 .toObject()[QStringLiteral("interval")]
                                 .toObject()[QStringLiteral("half_width_um")]
                                 .toDouble();
    EXPECT_TRUE(page.notes().contains(
        QStringLiteral("Prediction interval ±%1 µm (95 %): %2 % of the held-out readings")
            .arg(halfWidth, 0, 'f', 2)
            .arg(100 * coverage[QStringLiteral("share")].toDouble(), 0, 'f', 0)))
        << page.notes().toStdString();
    QString error;
    auto db = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, &error);
    const auto fits = db::modelFits(*db, 1);
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].model, QStringLiteral("mlr"));
    EXPECT_EQ(fits[0].test_runs, QStringList{QStringLiteral("S3")});
    EXPECT_DOUBLE_EQ(
        fits[0].metrics[QStringLiteral("test")].toObject()[QStringLiteral("rms_um")].toDouble(),
        cliRms);
}

TEST(ModelsPage, crossStateMatrixHoldsTheCliComparisonColouredGreenToRed) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kTwoRuns, QStringLiteral("compare.db"));
    auto window = windowOn(store);
    ui::ModelsPage& page = *window->modelsPage();
    choose(page.setupPanel()->modelBox(), QStringLiteral("heat-transfer"));
    QTest::mouseClick(page.fitButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));
    QTest::mouseClick(page.compareButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));
    EXPECT_TRUE(page.status().startsWith(QStringLiteral("Compared 7 models")))
        << page.status().toStdString();

    const QJsonObject cli =
        cliJson({QStringLiteral("compare"), QStringLiteral("--db"), store,
                 QStringLiteral("--campaign"), QStringLiteral("1"), QStringLiteral("--json")});
    const QJsonArray runs = cli[QStringLiteral("runs")].toArray();
    const ui::CrossStateMatrixModel& m = *page.matrixModel();
    ASSERT_EQ(m.columnCount(), runs.size());
    ASSERT_EQ(m.rowCount(), 7 * runs.size());
    double lowest = INFINITY, highest = -INFINITY;
    for (int row = 0; row < m.rowCount(); ++row) {
        const QString header = m.headerData(row, Qt::Vertical).toString();
        const QString model = header.section(QStringLiteral(" · "), 0, 0);
        const int i = row % int(runs.size());
        const QJsonArray cliRow = cli[QStringLiteral("models")]
                                      .toObject()[model]
                                      .toObject()[QStringLiteral("rms_um")]
                                      .toArray()[i]
                                      .toArray();
        for (int j = 0; j < m.columnCount(); ++j) {
            const QModelIndex cell = m.index(row, j);
            const double v = cell.data(ui::CrossStateMatrixModel::kRmsRole).toDouble();
            EXPECT_NEAR(v, cliRow[j].toDouble(), 1e-9 * std::max(1.0, v)) << header.toStdString();
            EXPECT_EQ(cell.data(Qt::BackgroundRole).value<QColor>(),
                      ui::CrossStateMatrixModel::rmsColour(v, m.minimumRms(), m.maximumRms()));
            EXPECT_EQ(cell.data().toString().startsWith(QLatin1Char('(')), i == j);
            lowest = std::min(lowest, v);
            highest = std::max(highest, v);
        }
    }
    EXPECT_DOUBLE_EQ(m.minimumRms(), lowest);
    EXPECT_DOUBLE_EQ(m.maximumRms(), highest);
    EXPECT_EQ(ui::CrossStateMatrixModel::rmsColour(lowest, lowest, highest).hue(), 120);  // green
    EXPECT_EQ(ui::CrossStateMatrixModel::rmsColour(highest, lowest, highest).hue(), 0);   // red
}

TEST(ModelsPage, cancelOfTheComparisonEndsCancelledAndShowsNothing) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kFiveRuns, QStringLiteral("five.db"));
    auto window = windowOn(store);
    ui::ModelsPage& page = *window->modelsPage();
    QTest::mouseClick(page.compareButton(), Qt::LeftButton);
    ASSERT_TRUE(page.job()->isRunning());
    EXPECT_TRUE(page.cancelButton()->isEnabled());
    QTest::mouseClick(page.cancelButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));
    EXPECT_TRUE(page.status().contains(QStringLiteral("cancelled"))) << page.status().toStdString();
    EXPECT_EQ(page.matrixModel()->rowCount(), 0);
    EXPECT_EQ(storedFits(store), 0u);
    EXPECT_TRUE(page.compareButton()->isEnabled());
}

TEST(ModelsPage, cancelOfAHeatTransferFitOnFiveRunsStoresNothing) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kFiveRuns, QStringLiteral("five.db"));
    auto window = windowOn(store);
    ui::ModelsPage& page = *window->modelsPage();
    choose(page.setupPanel()->modelBox(), QStringLiteral("heat-transfer"));
    const QStringList all{"S1", "S2", "S3", "S4", "S5"};
    check(page.setupPanel()->testList(), {});
    check(page.setupPanel()->trainList(), all);
    ASSERT_EQ(page.setupPanel()->trainRuns(), all);
    QTest::mouseClick(page.fitButton(), Qt::LeftButton);
    QTest::mouseClick(page.cancelButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));
    EXPECT_TRUE(page.status().contains(QStringLiteral("cancelled"))) << page.status().toStdString();
    EXPECT_EQ(storedFits(store), 0u);
    EXPECT_EQ(page.parametersModel()->rowCount(), 0);
}

TEST(ModelsPage, aCancelledHeatTransferFitStopsAtTheFirstSolverIteration) {
    // What makes Cancel prompt: the solver asks between iterations, not at the end.
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kFiveRuns, QStringLiteral("five.db"));
    QString note, error;
    const auto campaign = ui::loadCampaignForModels(store, 1, &note, &error);
    ASSERT_TRUE(campaign) << error.toStdString();
    const auto data = models::buildDataset(*campaign, {"S1", "S2", "S3", "S4", "S5"});
    ASSERT_TRUE(data.ok());
    models::HeatTransferModel model;
    int asked = 0;
    model.setCancelCheck([&] { return ++asked >= 1; });
    const models::FitSummary fit = model.fit(data.runs);
    EXPECT_FALSE(fit.success);
    EXPECT_TRUE(fit.message.contains(QStringLiteral("fit cancelled after 1 iterations")))
        << fit.message.toStdString();
    EXPECT_LE(asked, 3);
}

TEST(ModelsPage, pagesFitTheSmallestSupportedWindow) {
    ui::MainWindow window;
    EXPECT_LE(window.modelsPage()->minimumSizeHint().width(), 1000);
    EXPECT_LE(window.diagnosisPage()->minimumSizeHint().width(), 1000);
}
