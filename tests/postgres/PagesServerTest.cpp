// The ISO 230-3 and sensor-health pages on a lab store as on a SQLite file:
// a campaign whose T_bearing_fixed shorts for 50 s of run S1, imported with
// the real CLI into a database of the test cluster and opened by URL; the
// ISO 230-3 page shows the figures of `iso230-3 --db URL --json`, "Check
// run" stores the flag on the server, and a stretch kept in the page is kept
// by `fit --db URL`.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QItemSelectionModel>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>

#include "core/iso/Iso230_3Json.h"
#include "tests/postgres/PgTestServer.h"
#include "tests/support/CliRunner.h"
#include "tests/support/SignalWait.h"
#include "tests/ui/ShortedSensorStore.h"
#include "ui/models/SensorFlagModel.h"
#include "ui/pages/Iso230_3Page.h"
#include "ui/pages/SensorHealthPage.h"
#include "ui/shell/Session.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(ServerStorePages, iso230_3AndSensorHealthWorkOnALabStore) {
    if (const QString why = PgTestServer::skipReason(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    QTemporaryDir dir;
    const QString url = PgTestServer::freshDatabase(QStringLiteral("pages_server"));
    const CliResult imported =
        runCli({QStringLiteral("import"), QStringLiteral("--db"), url, shortedSensorBundle(dir)});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();

    ui::Session session;
    ui::Iso230_3Page iso{session};
    ui::SensorHealthPage health{session};
    QSignalSpy evaluated{&iso, &ui::Iso230_3Page::evaluated};
    QSignalSpy shown{&health, &ui::SensorHealthPage::flagsShown};
    QString error;
    ASSERT_TRUE(session.openStore(url, false, &error)) << qPrintable(error);
    session.selectCampaign(1);
    ASSERT_TRUE(waitFor(evaluated));
    ASSERT_TRUE(waitFor(shown));

    // The moving run S1's drift, as the CLI evaluates it on the same store.
    if (iso.runBox()->currentData().toString() != QStringLiteral("S1")) {
        evaluated.clear();
        iso.runBox()->setCurrentIndex(iso.runBox()->findData(QStringLiteral("S1")));
        ASSERT_TRUE(waitFor(evaluated));
    }
    ASSERT_TRUE(iso.drift());
    const CliResult cli =
        runCli({QStringLiteral("iso230-3"), QStringLiteral("--db"), url,
                QStringLiteral("--campaign"), QStringLiteral("1"), QStringLiteral("--run"),
                QStringLiteral("S1"), QStringLiteral("--json")});
    ASSERT_EQ(cli.exitCode, 0) << cli.err.constData();
    QJsonObject expected =
        QJsonDocument::fromJson(cli.out).object()[QStringLiteral("runs")][0].toObject();
    for (const char* key : {"run", "kind", "acceptance"}) expected.remove(QLatin1String(key));
    EXPECT_EQ(iso::runDriftJson(*iso.drift()), expected);

    // Check run and Keep in fits write to the server; the CLI's fit sees the choice.
    health.runBox()->setCurrentIndex(health.runBox()->findData(QStringLiteral("S1")));
    shown.clear();
    health.checkButton()->click();
    ASSERT_TRUE(waitFor(shown));
    ASSERT_EQ(health.flagModel()->rowCount(), 1) << qPrintable(error);
    EXPECT_EQ(health.flagModel()
                  ->data(health.flagModel()->index(0, ui::SensorFlagModel::Kind), Qt::UserRole)
                  .toString(),
              QStringLiteral("out_of_range"));
    health.flagView()->selectAll();
    shown.clear();
    health.keepButton()->click();
    ASSERT_TRUE(waitFor(shown));
    EXPECT_TRUE(health.flagModel()
                    ->data(health.flagModel()->index(0, ui::SensorFlagModel::InFits), Qt::UserRole)
                    .toBool());
    const CliResult fit =
        runCli({QStringLiteral("fit"), QStringLiteral("--db"), url, QStringLiteral("--campaign"),
                QStringLiteral("1"), QStringLiteral("--model"), QStringLiteral("mlr"),
                QStringLiteral("--train"), QStringLiteral("S1"), QStringLiteral("--test"),
                QStringLiteral("S3")});
    EXPECT_EQ(fit.exitCode, 0) << fit.err.constData();
    EXPECT_TRUE(fit.err.contains("flags: 0 samples of 0 channels left out, 1 flagged stretch kept"))
        << fit.err.constData();
}
