// The ISO 230-2 page driven through its widgets: for the run and edition
// chosen, every axis figure and every per-target value equals what
// `driftlab-cli iso230-2 --json` reports on the same store and run.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <cmath>

#include "tests/ui/UiTestSupport.h"
#include "ui/models/Iso230_2TargetModel.h"
#include "ui/pages/Iso230_2Page.h"
#include "ui/shell/Session.h"
#include "ui/widgets/Iso230_2Plot.h"

using namespace driftlab;
using namespace driftlab::test;
using TargetModel = ui::Iso230_2TargetModel;

namespace {

QJsonObject cliEvaluation(const QString& db, qint64 campaign, const QString& edition) {
    const CliResult r = runCli({QStringLiteral("iso230-2"), QStringLiteral("--db"), db,
                                QStringLiteral("--campaign"), QString::number(campaign),
                                QStringLiteral("--run"), QStringLiteral("S1"),
                                QStringLiteral("--edition"), edition, QStringLiteral("--json")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out).object();
}

QString shown(const QJsonValue& v) {
    return v.isDouble() ? QString::number(v.toDouble(), 'f', 3) : QStringLiteral("n/a");
}

void expectSameNumber(const QVariant& page, const QJsonValue& cli, const char* what) {
    if (!cli.isDouble()) {
        EXPECT_TRUE(std::isnan(page.toDouble())) << what;
        return;
    }
    EXPECT_DOUBLE_EQ(page.toDouble(), cli.toDouble()) << what;
}

}  // namespace

TEST(Iso230_2Page, figuresAndTargetsEqualTheCliJsonForTheSameRun) {
    QTemporaryDir dir;
    qint64 campaign = 0;
    const QString db = importExample(dir, &campaign);
    ui::Session session;
    QString error;
    ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
    ui::Iso230_2Page page(session);
    QSignalSpy evaluated(&page, &ui::Iso230_2Page::evaluated);
    session.selectCampaign(campaign);
    ASSERT_TRUE(waitFor(evaluated));
    ASSERT_EQ(page.runBox()->currentText(), QStringLiteral("S1"));

    for (const QString& edition : {QStringLiteral("2014"), QStringLiteral("1997")}) {
        SCOPED_TRACE(edition.toStdString());
        page.editionBox()->setCurrentIndex(page.editionBox()->findData(edition));
        ASSERT_TRUE(page.evaluation().has_value()) << qPrintable(page.messageLabel()->text());
        const QJsonObject cli = cliEvaluation(db, campaign, edition);
        EXPECT_TRUE(
            page.messageLabel()->text().contains(cli[QStringLiteral("standard")].toString()));
        for (const char* key : {"A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up",
                                "R_down", "B", "B_mean"})
            EXPECT_EQ(page.figureText(QLatin1String(key)), shown(cli[QLatin1String(key)])) << key;

        const QJsonArray targets = cli[QStringLiteral("targets")].toArray();
        const TargetModel* m = page.targetModel();
        ASSERT_EQ(m->rowCount(), targets.size());
        const std::pair<int, const char*> columns[] = {
            {TargetModel::Target, "target_mm"},   {TargetModel::MeanUp, "mean_up"},
            {TargetModel::MeanDown, "mean_down"}, {TargetModel::Mean, "mean"},
            {TargetModel::SUp, "s_up"},           {TargetModel::SDown, "s_down"},
            {TargetModel::Reversal, "B"},         {TargetModel::RUp, "R_up"},
            {TargetModel::RDown, "R_down"},       {TargetModel::R, "R"}};
        for (int row = 0; row < m->rowCount(); ++row) {
            const QJsonObject t = targets[row].toObject();
            for (const auto& [column, key] : columns)
                expectSameNumber(m->data(m->index(row, column), Qt::UserRole),
                                 t[QLatin1String(key)], key);
            EXPECT_EQ(m->data(m->index(row, TargetModel::CountUp)).toInt(), t["n_up"].toInt());
        }
        EXPECT_EQ(page.warningLabel()->text().isEmpty(),
                  cli[QStringLiteral("warnings")].toArray().isEmpty() &&
                      cli[QStringLiteral("skipped")].toArray().isEmpty());
        EXPECT_GE(page.plot()->graphCount(), 2);  // both directions
    }
}

TEST(Iso230_2Page, aCampaignWithoutPositioningReadingsIsNamed) {
    QTemporaryDir dir;
    ui::Session session;
    QString error;
    ASSERT_TRUE(session.openStore(dir.filePath(QStringLiteral("empty.sqlite")), true, &error))
        << qPrintable(error);
    ui::Iso230_2Page page(session);
    EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("Select a campaign")));
    EXPECT_FALSE(page.evaluation().has_value());
}
