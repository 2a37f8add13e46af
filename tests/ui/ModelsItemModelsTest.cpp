// Every item model of the Models and Diagnosis pages under
// QAbstractItemModelTester (fatal on any violation), empty and filled.
#include <QAbstractItemModelTester>
#include <QJsonArray>
#include <cmath>

#include "ModelsTestSupport.h"
#include "ui/models/CrossStateMatrixModel.h"
#include "ui/models/FindingsModel.h"
#include "ui/models/ModelParametersModel.h"
#include "ui/models/StoredDiagnosesModel.h"
#include "ui/models/TestScoresModel.h"

using namespace driftlab;

namespace {

void testerOn(QAbstractItemModel* model) {
    new QAbstractItemModelTester(model, QAbstractItemModelTester::FailureReportingMode::Fatal,
                                 model);
}

}  // namespace

TEST(ModelsItemModels, crossStateMatrixModelPassesTheTester) {
    ui::CrossStateMatrixModel m;
    testerOn(&m);
    models::CrossStateMatrix a{
        {"S1", "S3"}, {{0.4, 0.5}, {NAN, 0.41}}, {"fit on run 'S3': x"}, false};
    models::CrossStateMatrix b{{"S1", "S3"}, {{1.0, 29.0}, {2.0, 1.5}}, {}, false};
    m.setMatrices({"S1", "S3"}, {{"heat-transfer", a}, {"mlr", b}});
    EXPECT_EQ(m.rowCount(), 4);
    EXPECT_EQ(m.columnCount(), 2);
    EXPECT_EQ(m.index(0, 0).data().toString(), QStringLiteral("(0.40)"));
    EXPECT_EQ(m.index(1, 0).data().toString(), QStringLiteral("—"));
    EXPECT_EQ(m.headerData(2, Qt::Vertical).toString(), QStringLiteral("mlr · S1"));
    EXPECT_EQ(m.errors(), QStringList{QStringLiteral("heat-transfer: fit on run 'S3': x")});
    // Green for the lowest, red for the highest, something between in between.
    const int mid = m.index(2, 0).data(Qt::BackgroundRole).value<QColor>().hue();
    EXPECT_EQ(m.index(0, 0).data(Qt::BackgroundRole).value<QColor>().hue(), 120);
    EXPECT_EQ(m.index(2, 1).data(Qt::BackgroundRole).value<QColor>().hue(), 0);
    EXPECT_GT(mid, 0);
    EXPECT_LT(mid, 120);
    m.clear();
    EXPECT_EQ(m.rowCount(), 0);
}

TEST(ModelsItemModels, parameterAndScoreModelsPassTheTester) {
    ui::ModelParametersModel parameters;
    testerOn(&parameters);
    parameters.setParameters(
        {{"h", {12.04, 0.003, "W/(m²·K)"}}, {"c_b", {0.02, NAN, "W/(rad/s)"}}});
    ASSERT_EQ(parameters.rowCount(), 2);
    EXPECT_EQ(parameters.index(0, ui::ModelParametersModel::Sigma).data().toString(),
              QStringLiteral("—"));  // c_b first (sorted), σ undetermined
    EXPECT_EQ(parameters.index(1, ui::ModelParametersModel::Unit).data().toString(),
              QStringLiteral("W/(m²·K)"));

    ui::TestScoresModel scores;
    testerOn(&scores);
    models::Score s;
    s.rms_um = 0.39;
    s.peak_um = 1.3;
    s.uncompensated_rms_um = 55;
    s.reduction = 0.993;
    scores.setRows({{"S3", s}, {"all", models::Score{}}});
    EXPECT_EQ(scores.index(0, ui::TestScoresModel::Reduction).data().toString(),
              QStringLiteral("99.3"));
    EXPECT_EQ(scores.index(1, ui::TestScoresModel::Rms).data().toString(), QStringLiteral("—"));
}

TEST(ModelsItemModels, findingsAndStoredDiagnosesModelsPassTheTester) {
    ui::FindingsModel findings;
    testerOn(&findings);
    diagnosis::Finding f;
    f.cause = QStringLiteral("forced_convection");
    f.parameters = {{QStringLiteral("dh_800rpm"), {3.5, 0.1, QStringLiteral("W/(m²·K)")}},
                    {QStringLiteral("m"), {1.4, 0.05, QString()}}};
    f.gain = {QStringLiteral("positioning"), QStringLiteral("µm"), 3.0, 0.3, 0.9, {}};
    f.evidence = QStringLiteral("convection grows with screw speed");
    f.confidence = 0.973;
    diagnosis::Finding g = f;
    g.cause = QStringLiteral("motor_heat");
    findings.setFindings({f, g}, QStringLiteral("forced_convection"));
    EXPECT_EQ(findings.verdictRow(), 0);
    EXPECT_TRUE(findings.index(0, 0).data(Qt::FontRole).value<QFont>().bold());
    EXPECT_FALSE(findings.index(1, 0).data(Qt::FontRole).value<QFont>().bold());
    EXPECT_EQ(findings.index(0, ui::FindingsModel::Gain).data().toString(), QStringLiteral("90.0"));
    EXPECT_EQ(findings.index(0, ui::FindingsModel::Confidence).data().toString(),
              QStringLiteral("0.97"));
    EXPECT_EQ(findings.index(0, ui::FindingsModel::RmsAfter).data().toString(),
              QStringLiteral("0.30 µm"));
    EXPECT_EQ(findings.index(0, ui::FindingsModel::Parameter).data().toString(),
              QStringLiteral("dh_800rpm = 3.5 ± 0.1 W/(m²·K), m = 1.4 ± 0.05"));
    findings.setFindings({}, QStringLiteral("none"));
    EXPECT_EQ(findings.verdictRow(), -1);

    ui::StoredDiagnosesModel stored;
    testerOn(&stored);
    db::DiagnosisRecord d{7, "screw-fdm", "none", std::nullopt,
                          QJsonObject{{"train_runs", QJsonArray{"S1"}},
                                      {"test_runs", QJsonArray{"S3"}},
                                      {"base", QJsonObject{{"test_rms_um", 0.41}}}}};
    stored.setDiagnoses({d, {8, "screw-fdm", "forced_convection", 3, {}}});
    EXPECT_EQ(stored.index(0, ui::StoredDiagnosesModel::BaseRms).data().toString(),
              QStringLiteral("0.41"));
    EXPECT_EQ(stored.index(1, ui::StoredDiagnosesModel::AdoptedFit).data().toString(),
              QStringLiteral("3"));
}
