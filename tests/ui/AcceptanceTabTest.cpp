// The ISO 230-2 page's acceptance tab driven through its widgets: a
// specification opened there gives the verdicts `driftlab-cli iso230-2 --spec`
// gives on the same store and run; a tolerance typed into the table changes
// the verdict by ISO 14253-1, and the specification saved from the page is
// one the CLI reads to the same verdicts.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>

#include "tests/support/BundleTestSupport.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/AcceptanceModel.h"
#include "ui/pages/Iso230_2Page.h"
#include "ui/shell/Session.h"
#include "ui/widgets/Iso230_2Plot.h"

using namespace driftlab;
using namespace driftlab::test;
using Model = ui::AcceptanceModel;

namespace {

const QString kSpec =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-acceptance.json");

QJsonArray cliDecisions(const QString& db, qint64 campaign, const QString& spec) {
    const CliResult r = runCli({QStringLiteral("iso230-2"), QStringLiteral("--db"), db,
                                QStringLiteral("--campaign"), QString::number(campaign),
                                QStringLiteral("--spec"), spec, QStringLiteral("--json")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out)
        .object()
        .value(QStringLiteral("acceptance"))
        .toObject()
        .value(QStringLiteral("decisions"))
        .toArray();
}

/// The row of the table for an axis value ("A", "R", …).
int rowOf(const Model& m, const QString& key) {
    for (int row = 0; row < m.rowCount(); ++row)
        if (m.data(m.index(row, Model::Value)).toString() == key) return row;
    return -1;
}

void expectSameVerdicts(const Model& m, const QJsonArray& cli) {
    int decided = 0;
    for (int row = 0; row < m.rowCount(); ++row)
        decided += !m.data(m.index(row, Model::Verdict)).toString().isEmpty();
    EXPECT_EQ(decided, cli.size());
    for (const QJsonValue& v : cli) {
        const QJsonObject d = v.toObject();
        const int row = rowOf(m, d.value(QStringLiteral("parameter")).toString());
        ASSERT_GE(row, 0);
        EXPECT_EQ(m.data(m.index(row, Model::Verdict)).toString(),
                  d.value(QStringLiteral("verdict")).toString());
        EXPECT_EQ(
            m.data(m.index(row, Model::Uncertainty)).toString(),
            QString::number(d.value(QStringLiteral("expanded_uncertainty_um")).toDouble(), 'f', 3));
        EXPECT_EQ(m.data(m.index(row, Model::Result)).toString(),
                  QString::number(d.value(QStringLiteral("value_um")).toDouble(), 'f', 3));
    }
}

}  // namespace

/// The example campaign imported into a store and shown on the page.
class AcceptanceTab : public ::testing::Test {
protected:
    void SetUp() override {
        db = importExample(dir, &campaign);
        QString error;
        ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
        session.selectCampaign(campaign);
        ASSERT_TRUE(waitFor(evaluated));
    }

    QTemporaryDir dir;
    qint64 campaign = 0;
    QString db;
    ui::Session session;
    ui::Iso230_2Page page{session};
    QSignalSpy evaluated{&page, &ui::Iso230_2Page::evaluated};
};

TEST_F(AcceptanceTab, verdictsEqualTheCliAndFollowAnEditedTolerance) {
    EXPECT_FALSE(page.acceptance().has_value());  // the example carries no specification

    ASSERT_TRUE(page.loadSpecification(kSpec));
    ASSERT_TRUE(page.acceptance().has_value()) << qPrintable(page.messageLabel()->text());
    Model& m = *page.acceptanceModel();
    expectSameVerdicts(m, cliDecisions(db, campaign, kSpec));
    // The readings are at 20 °C and the plot draws the tolerance of A.
    EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("normalised to 20 °C")));
    const int graphsWithTolerance = page.plot()->graphCount();

    // A tolerance on R just above its result plus U: PASS, as the rule says.
    const int r = rowOf(m, QStringLiteral("R"));
    const double result = m.data(m.index(r, Model::Result)).toDouble();
    const double U = m.data(m.index(r, Model::Uncertainty)).toDouble();
    evaluated.clear();
    ASSERT_TRUE(m.setData(m.index(r, Model::Tolerance), QString::number(result + U + 0.01)));
    ASSERT_TRUE(waitFor(evaluated));
    EXPECT_EQ(m.data(m.index(r, Model::Verdict)).toString(), QStringLiteral("PASS"));
    // Clearing A's tolerance removes its verdict and its lines.
    const int a = rowOf(m, QStringLiteral("A"));
    evaluated.clear();
    ASSERT_TRUE(m.setData(m.index(a, Model::Tolerance), QString()));
    ASSERT_TRUE(waitFor(evaluated));
    EXPECT_TRUE(m.data(m.index(a, Model::Verdict)).toString().isEmpty());
    EXPECT_EQ(page.plot()->graphCount(), graphsWithTolerance - 2);
    // A tolerance that is no number is refused and changes nothing.
    EXPECT_FALSE(m.setData(m.index(a, Model::Tolerance), QStringLiteral("ten")));
    EXPECT_FALSE(m.setData(m.index(a, Model::Tolerance), QStringLiteral("-3")));

    // Saved from the page, read by the CLI: the same verdicts.
    const QString saved = dir.filePath(QStringLiteral("edited.json"));
    ASSERT_TRUE(page.saveSpecification(saved));
    expectSameVerdicts(m, cliDecisions(db, campaign, saved));
}

TEST_F(AcceptanceTab, aBadSpecificationIsNamedAndTheEvaluationKept) {
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    writeFile(bad, R"({"axes": {"X": {"iso230_2_um": {"A": "ten"}}}})");
    EXPECT_FALSE(page.loadSpecification(bad));
    EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("axes.X.iso230_2_um.A")))
        << qPrintable(page.messageLabel()->text());
    EXPECT_TRUE(page.evaluation().has_value());
    EXPECT_FALSE(page.acceptance().has_value());
}
