// File → Open lab store… on the test cluster, through the dialog's fields and
// buttons: the server store opened in the window and listed in the recent
// stores, its spool's runs shown as not on the server yet, Upload now
// copying them, and the state read again.
#include <gtest/gtest.h>

#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "db/CampaignStore.h"
#include "db/StoreBackend.h"
#include "tests/postgres/PgTestServer.h"
#include "tests/support/CliRunner.h"
#include "tests/support/SignalWait.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/shell/SpoolSync.h"
#include "ui/widgets/LabStoreDialog.h"

using namespace driftlab;

TEST(LabStoreDialog, opensAServerStoreShowsItsSpoolAndUploadsIt) {
    if (const QString why = test::PgTestServer::skipReason(); !why.isEmpty())
        GTEST_SKIP() << why.toStdString();
    const QString url = test::PgTestServer::freshDatabase(QStringLiteral("ui_lab_store"));
    const QString example =
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state");
    QTemporaryDir dir;
    const QString spool = dir.filePath(QStringLiteral("spool.sqlite"));
    // The server store and a spool, each holding the example, made by the real CLI.
    for (const QString& store : {url, spool}) {
        const test::CliResult r =
            test::runCli({QStringLiteral("import"), example, QStringLiteral("--db"), store});
        ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    }

    QString error;
    int runs = 0;
    {
        auto reader = db::CampaignStore::open(spool, db::StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(reader) << error.toStdString();
        runs = reader->listCampaigns().at(0).runs;
    }
    ASSERT_GT(runs, 0);

    ui::MainWindow window;
    ui::LabStoreDialog* dialog = window.labStoreDialog();
    dialog->urlEdit()->setText(url);
    dialog->spoolEdit()->setText(spool);
    QSignalSpy state(dialog->spoolSync(), &ui::SpoolSync::stateChanged);
    QTest::mouseClick(dialog->openButton(), Qt::LeftButton);
    ASSERT_TRUE(test::waitFor(state));
    EXPECT_EQ(window.session().storePath(), url);
    EXPECT_EQ(QSettings().value(QStringLiteral("stores/recent")).toStringList().value(0),
              db::parseServerStoreUrl(url, nullptr)->display());
    EXPECT_TRUE(dialog->stateText().contains(QStringLiteral("%1 runs in the spool").arg(runs)));
    EXPECT_TRUE(dialog->stateText().contains(QStringLiteral("%1 not on the server yet").arg(runs)))
        << dialog->stateText().toStdString();

    QSignalSpy uploaded(dialog->spoolSync(), &ui::SpoolSync::uploaded);
    ASSERT_TRUE(dialog->uploadButton()->isEnabled());
    QTest::mouseClick(dialog->uploadButton(), Qt::LeftButton);
    ASSERT_TRUE(test::waitFor(uploaded));
    EXPECT_TRUE(uploaded.first().first().toBool())
        << uploaded.first().at(1).toString().toStdString();
    ASSERT_TRUE(test::waitFor(state, 2));
    EXPECT_TRUE(dialog->stateText().contains(QStringLiteral("0 not on the server yet")))
        << dialog->stateText().toStdString();
    EXPECT_TRUE(dialog->stateText().contains(QStringLiteral("last upload")));

    auto server = db::CampaignStore::open(url, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(server) << error.toStdString();
    EXPECT_EQ(server->listCampaigns().size(), 2u);  // its own and the spool's
}
