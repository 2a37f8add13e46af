// The ISO 230-2 page's "Machine history" tab on a real store: the campaigns of
// the selected campaign's machine axis, oldest first, with the figures that
// `driftlab-cli history --json` gives, in an item model that passes
// QAbstractItemModelTester, and the trend plot with one curve per figure.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QJsonArray>
#include <QJsonObject>
#include <QLabel>
#include <cmath>

#include "tests/support/BundleTestSupport.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/MachineHistoryModel.h"
#include "ui/pages/Iso230_2Page.h"
#include "ui/shell/Session.h"
#include "ui/widgets/MachineHistoryView.h"
#include "ui/widgets/PlotView.h"

using namespace driftlab;
using namespace driftlab::test;
using HistoryModel = ui::MachineHistoryModel;

TEST(MachineHistoryView, showsTheAxisCampaignsOldestFirstAsTheCliDoes) {
    QTemporaryDir dir;
    qint64 latest = 0;
    const QString db = importExample(dir, &latest);  // dated by its import: today
    // An earlier campaign of the same axis, its deviations half as large.
    const QString earlier = dir.filePath(QStringLiteral("earlier"));
    copyBundle(exampleBundlePath(), earlier);
    replaceInFile(earlier + QStringLiteral("/campaign.json"), "\"X axis moving-state example\"",
                  "\"X axis a year before\", \"date\": \"2025-06-30\"");
    rewriteColumn(earlier + QStringLiteral("/positioning.csv"), 5,
                  [](double v) { return QByteArray::number(v / 2, 'g', 17); });
    const CliResult imported =
        runCli({QStringLiteral("import"), earlier, QStringLiteral("--db"), db});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    const qint64 first = imported.out.trimmed().toLongLong();

    ui::Session session;
    QString error;
    ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
    ui::Iso230_2Page page(session);
    QSignalSpy loaded(page.historyView(), &ui::MachineHistoryView::loaded);
    session.selectCampaign(latest);
    ASSERT_TRUE(waitFor(loaded));

    HistoryModel* model = page.historyView()->model();
    QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    const CliResult r =
        runCli({QStringLiteral("history"), QStringLiteral("--db"), db, QStringLiteral("--machine"),
                QStringLiteral("VMC-850"), QStringLiteral("--axis"), QStringLiteral("X"),
                QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonArray campaigns = json(r)[QStringLiteral("campaigns")].toArray();
    ASSERT_EQ(campaigns.size(), 2);
    ASSERT_EQ(model->rowCount(), 2) << qPrintable(page.historyView()->messageLabel()->text());
    EXPECT_EQ(model->index(0, HistoryModel::Campaign).data(Qt::UserRole).toLongLong(), first);
    EXPECT_EQ(model->index(1, HistoryModel::Campaign).data(Qt::UserRole).toLongLong(), latest);
    EXPECT_EQ(model->index(0, HistoryModel::Date).data().toString(), QStringLiteral("2025-06-30"));
    const std::pair<int, const char*> columns[] = {{HistoryModel::A, "A"},
                                                   {HistoryModel::E, "E"},
                                                   {HistoryModel::R, "R"},
                                                   {HistoryModel::B, "B"},
                                                   {HistoryModel::M, "M"}};
    for (int row = 0; row < 2; ++row) {
        const QJsonObject iso = campaigns[row].toObject()[QStringLiteral("iso230_2")].toObject();
        for (const auto& [column, key] : columns) {
            EXPECT_DOUBLE_EQ(model->index(row, column).data(Qt::UserRole).toDouble(),
                             iso[QLatin1String(key)].toDouble())
                << key << " row " << row;
            EXPECT_EQ(model->index(row, column).data().toString(),
                      QString::number(iso[QLatin1String(key)].toDouble(), 'f', 3));
        }
    }
    // Half the deviations a year before: A has doubled since.
    const double a0 = model->index(0, HistoryModel::A).data(Qt::UserRole).toDouble();
    EXPECT_NEAR(model->index(1, HistoryModel::AChangeFromFirst).data(Qt::UserRole).toDouble(), a0,
                1e-9 * a0);
    EXPECT_EQ(page.historyView()->plot()->curveCount(), 5);
}
