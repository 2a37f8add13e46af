// The Diagnosis page through its widgets on stores made by the real CLI: a
// hidden effect is named, its evidence and plots shown, the diagnosis stored,
// the extension adopted as a model fit; Cancel stores nothing.
#include <QPushButton>
#include <QTabWidget>
#include <QTableView>

#include "ModelsTestSupport.h"
#include "db/DiagnosisStore.h"
#include "ui/models/FindingsModel.h"
#include "ui/models/StoredDiagnosesModel.h"
#include "ui/pages/DiagnosisPage.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/PlotView.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

std::unique_ptr<ui::MainWindow> diagnosisWindowOn(const QString& store) {
    auto window = std::make_unique<ui::MainWindow>();
    EXPECT_TRUE(window->openStore(store, false, false));
    window->session().selectCampaign(1);
    window->pages()->setCurrentWidget(window->diagnosisPage());
    window->show();
    window->resize(1280, 800);  // the smallest window the GUI supports
    return window;
}

std::vector<db::DiagnosisRecord> storedDiagnoses(const QString& path) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    return store ? db::diagnoses(*store, 1) : std::vector<db::DiagnosisRecord>{};
}

const QStringList kHiddenConvection{QStringLiteral("--runs"), QStringLiteral("S1,S3"),
                                    QStringLiteral("--effect"),
                                    QStringLiteral("forced_convection=0.05")};

}  // namespace

// About a minute: the base model and every candidate effect, fitted on S1.
TEST(DiagnosisPage, namesAHiddenEffectShowsItsEvidenceStoresItAndAdoptsTheExtension) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kHiddenConvection, QStringLiteral("fc.db"));
    auto window = diagnosisWindowOn(store);
    ui::DiagnosisPage& page = *window->diagnosisPage();
    ASSERT_TRUE(page.diagnoseButton()->isEnabled());
    QTest::mouseClick(page.diagnoseButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));

    EXPECT_EQ(page.verdict(), QStringLiteral("forced_convection")) << page.status().toStdString();
    ASSERT_GT(page.findingsModel()->rowCount(), 1);
    EXPECT_EQ(page.findingsModel()->verdictRow(), 0);
    EXPECT_TRUE(page.findingsModel()
                    ->index(0, ui::FindingsModel::Evidence)
                    .data()
                    .toString()
                    .contains(QStringLiteral("convection")));
    EXPECT_EQ(page.beforeAfter()->curveCount(), 3);  // measured, base, with the extension
    EXPECT_EQ(page.storedModel()->rowCount(), 1);
    auto stored = storedDiagnoses(store);
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(stored[0].verdict, QStringLiteral("forced_convection"));
    EXPECT_FALSE(stored[0].adopted_fit_id);

    // The verdict's row is selected: Adopt keeps its extension as a fit.
    ASSERT_TRUE(page.adoptButton()->isEnabled());
    QTest::mouseClick(page.adoptButton(), Qt::LeftButton);
    EXPECT_TRUE(page.status().contains(QStringLiteral("stored as fit")))
        << page.status().toStdString();
    EXPECT_FALSE(page.adoptButton()->isEnabled());  // adopted once
    QString error;
    auto db = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, &error);
    const auto fits = db::modelFits(*db, 1);
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].model, QStringLiteral("heat-transfer+forced_convection"));
    EXPECT_TRUE(fits[0].parameters.contains(QStringLiteral("dh_800rpm")));
    stored = storedDiagnoses(store);
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(stored[0].adopted_fit_id, std::optional<qint64>(fits[0].id));
    EXPECT_EQ(page.storedModel()->index(0, ui::StoredDiagnosesModel::AdoptedFit).data().toString(),
              QString::number(fits[0].id));
}

TEST(DiagnosisPage, cancelEndsCancelledAndStoresNothing) {
    QTemporaryDir dir;
    const QString store = simulatedStore(dir, kHiddenConvection, QStringLiteral("fc.db"));
    auto window = diagnosisWindowOn(store);
    ui::DiagnosisPage& page = *window->diagnosisPage();
    QTest::mouseClick(page.diagnoseButton(), Qt::LeftButton);
    ASSERT_TRUE(page.cancelButton()->isEnabled());
    QTest::mouseClick(page.cancelButton(), Qt::LeftButton);
    ASSERT_TRUE(waitForJob(*page.job()));
    EXPECT_TRUE(page.status().contains(QStringLiteral("cancelled"))) << page.status().toStdString();
    EXPECT_TRUE(storedDiagnoses(store).empty());
    EXPECT_EQ(page.findingsModel()->rowCount(), 0);
    EXPECT_TRUE(page.diagnoseButton()->isEnabled());
}
