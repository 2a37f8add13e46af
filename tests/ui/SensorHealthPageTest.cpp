// The sensor-health page driven through its widgets on a real store: a
// simulated campaign whose T_bearing_fixed shorts (−50 °C) for 60 s of run S1
// is imported with the real CLI; "Check run" stores the flag; keeping the
// stretch gives the GUI's fit of `driftlab-cli fit --keep-flagged`, leaving
// it out again the fit of plain `fit`, and the CLI honours the same choice.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <algorithm>
#include <map>

#include "db/CampaignStore.h"
#include "db/ModelFitStore.h"
#include "tests/ui/ShortedSensorStore.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/SensorFlagModel.h"
#include "ui/pages/Iso230_3Page.h"
#include "ui/pages/SensorHealthPage.h"
#include "ui/shell/FitJob.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/SensorFlagTimeline.h"

using namespace driftlab;
using namespace driftlab::test;
using FlagModel = ui::SensorFlagModel;

/// The shorted campaign in a store, shown on the page with run S1 chosen.
class SensorHealthPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        db = importedStore(dir, shortedSensorBundle(dir));
        QString error;
        ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
        session.selectCampaign(1);
        ASSERT_TRUE(waitFor(shown));
        page.runBox()->setCurrentIndex(page.runBox()->findData(QStringLiteral("S1")));
        ASSERT_EQ(page.runBox()->currentData().toString(), QStringLiteral("S1"));
    }

    /// Clicks `button` and waits for the flags shown after the change.
    void click(QPushButton* button) {
        shown.clear();
        ASSERT_TRUE(button->isEnabled());
        button->click();
        ASSERT_TRUE(waitFor(shown));
    }

    /// `driftlab-cli fit` of mlr on S1, tested on S3, with `extra`: its parameters.
    QJsonObject cliFit(const QStringList& extra = {}, QByteArray* err = nullptr) {
        const CliResult r =
            runCli(QStringList{
                       QStringLiteral("fit"), QStringLiteral("--db"), db,
                       QStringLiteral("--campaign"), QStringLiteral("1"), QStringLiteral("--model"),
                       QStringLiteral("mlr"), QStringLiteral("--train"), QStringLiteral("S1"),
                       QStringLiteral("--test"), QStringLiteral("S3"), QStringLiteral("--json")} +
                   extra);
        EXPECT_EQ(r.exitCode, 0) << r.err.constData();
        if (err) *err = r.err;
        return QJsonDocument::fromJson(r.out).object()[QStringLiteral("parameters")].toObject();
    }

    /// The same fit as the Models page runs it (ui::runFit): the stored record's parameters.
    QJsonObject guiFit(QString* note, QJsonObject* leftOut = nullptr) {
        ui::JobControl control;
        const ui::FitOutcome out = ui::runFit({db,
                                               1,
                                               QStringLiteral("mlr"),
                                               QString(),
                                               {QStringLiteral("S1")},
                                               {QStringLiteral("S3")}},
                                              control);
        EXPECT_TRUE(out.error.isEmpty() && out.fit_id) << qPrintable(out.error);
        *note = out.note;
        QString error;
        auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
        EXPECT_TRUE(store) << qPrintable(error);
        const std::vector<db::ModelFitRecord> fits = db::modelFits(*store, 1);
        EXPECT_FALSE(fits.empty());
        if (leftOut && !fits.empty())
            *leftOut = fits.back().metrics[QStringLiteral("flagged_left_out")].toObject();
        return fits.empty() ? QJsonObject() : fits.back().parameters;
    }

    QVariant cell(int row, int column, int role = Qt::UserRole) const {
        return page.flagModel()->data(page.flagModel()->index(row, column), role);
    }

    QTemporaryDir dir;
    QString db;
    ui::Session session;
    ui::SensorHealthPage page{session};
    QSignalSpy shown{&page, &ui::SensorHealthPage::flagsShown};
};

TEST_F(SensorHealthPageTest, keepingAndMaskingAStretchChangesTheFitAsTheCliDoes) {
    EXPECT_EQ(page.flagModel()->rowCount(), 0);  // nothing checked yet
    EXPECT_FALSE(page.keepButton()->isEnabled());
    const QJsonObject asLogged = cliFit({QStringLiteral("--keep-flagged")});

    click(page.checkButton());
    ASSERT_EQ(page.flagModel()->rowCount(), 1) << qPrintable(page.messageLabel()->text());
    EXPECT_EQ(cell(0, FlagModel::Channel, Qt::DisplayRole).toString(),
              QStringLiteral("T_bearing_fixed"));
    EXPECT_EQ(cell(0, FlagModel::Kind).toString(), QStringLiteral("out_of_range"));
    EXPECT_EQ(cell(0, FlagModel::From).toDouble(), 700);
    EXPECT_EQ(cell(0, FlagModel::To).toDouble(), 750);
    EXPECT_EQ(cell(0, FlagModel::Samples).toInt(), 6);
    EXPECT_FALSE(cell(0, FlagModel::InFits).toBool());
    EXPECT_TRUE(page.summaryLabel()->text().contains(QStringLiteral("6 samples left out")))
        << qPrintable(page.summaryLabel()->text());
    EXPECT_GT(page.timeline()->channelRows(), 1);
    EXPECT_EQ(page.timeline()->leftOutBars(), 1);

    // Every flag left out (the default): the GUI's fit is plain `fit`'s.
    QByteArray err;
    const QJsonObject masked = cliFit({}, &err);
    EXPECT_TRUE(err.contains("flags: 6 samples of 1 channel left out")) << err.constData();
    QString note;
    QJsonObject leftOut;
    EXPECT_EQ(guiFit(&note, &leftOut), masked);
    EXPECT_NE(masked, asLogged);
    // The stored fit names what it did not see.
    EXPECT_EQ(leftOut[QStringLiteral("samples")].toInt(), 6);
    EXPECT_EQ(leftOut[QStringLiteral("channels")].toArray(),
              QJsonArray{QStringLiteral("T_bearing_fixed")});
    EXPECT_TRUE(note.contains(QStringLiteral("6 flagged samples of 1 channel(s) left out")))
        << qPrintable(note);
    EXPECT_TRUE(note.contains(QStringLiteral("S1 T_bearing_fixed out_of_range")))
        << qPrintable(note);

    // Kept: the GUI's fit and the CLI's are those of the data as logged.
    page.flagView()->selectAll();
    click(page.keepButton());
    ASSERT_EQ(page.flagModel()->rowCount(), 1);
    EXPECT_TRUE(cell(0, FlagModel::InFits).toBool());
    EXPECT_TRUE(page.summaryLabel()->text().contains(QStringLiteral("0 samples left out")))
        << qPrintable(page.summaryLabel()->text());
    EXPECT_EQ(page.timeline()->keptBars(), 1);
    EXPECT_EQ(guiFit(&note, &leftOut), asLogged);
    EXPECT_TRUE(note.contains(QStringLiteral("1 flagged stretch(es) kept"))) << qPrintable(note);
    EXPECT_EQ(leftOut[QStringLiteral("samples")].toInt(), 0);
    EXPECT_EQ(leftOut[QStringLiteral("kept")].toInt(), 1);
    EXPECT_EQ(cliFit({}, &err), asLogged);
    EXPECT_TRUE(err.contains("flags: 0 samples of 0 channels left out, 1 flagged stretch kept"))
        << err.constData();

    // Checked again, the stretch stays kept; left out again, the fit is the masked one.
    click(page.checkButton());
    EXPECT_TRUE(cell(0, FlagModel::InFits).toBool());
    page.flagView()->selectAll();
    click(page.leaveOutButton());
    EXPECT_FALSE(cell(0, FlagModel::InFits).toBool());
    EXPECT_EQ(guiFit(&note), masked);
    EXPECT_EQ(cliFit(), masked);
}

TEST(SensorHealthRedundantPair, aPairDriftingApartIsFlaggedOnBothChannelsAsTheCliFindsIt) {
    // T_bed rewritten in run S1 as a second ambient sensor in T_ambient's
    // housing, 0.05 K apart, that decalibrates from 5000 s on (0.5 mK/s, up
    // to 1 K): too slow for the single-channel checks, found only as a pair.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("redundant"));
    copyBundle(simulatedCampaign(QStringLiteral("S1,S3"), 3), bundle);
    QList<QByteArray> lines = readFile(bundle + "/samples.csv").split('\n');
    const QList<QByteArray> header = lines[0].split(',');
    const int ambient = int(header.indexOf("T_ambient"));
    const int bed = int(header.indexOf("T_bed"));
    ASSERT_GT(ambient, 1);
    ASSERT_GT(bed, 1);
    for (QByteArray& line : lines) {
        QList<QByteArray> f = line.split(',');
        if (f.size() != header.size() || f[0] != "S1") continue;
        const double drift_K = std::clamp((f[1].toDouble() - 5000.0) * 0.0005, 0.0, 1.0);
        f[bed] = QByteArray::number(f[ambient].toDouble() + 0.05 + drift_K, 'f', 3);
        line = f.join(',');
    }
    writeFile(bundle + "/samples.csv", lines.join('\n'));
    const QString db = importedStore(dir, bundle);

    ui::Session session;
    ui::SensorHealthPage page{session};
    QSignalSpy shown{&page, &ui::SensorHealthPage::flagsShown};
    QString error;
    ASSERT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
    session.selectCampaign(1);
    ASSERT_TRUE(waitFor(shown));
    page.runBox()->setCurrentIndex(page.runBox()->findData(QStringLiteral("S1")));

    // Without the pair nothing is found; a pair that is not two channels is named.
    shown.clear();
    page.checkButton()->click();
    ASSERT_TRUE(waitFor(shown));
    EXPECT_EQ(page.flagModel()->rowCount(), 0);
    page.redundantPairs()->setText(QStringLiteral("T_ambient"));
    page.checkButton()->click();
    EXPECT_TRUE(page.messageLabel()->text().contains(QStringLiteral("A=B")))
        << qPrintable(page.messageLabel()->text());
    EXPECT_EQ(page.flagModel()->rowCount(), 0);

    page.redundantPairs()->setText(QStringLiteral(" T_ambient = T_bed "));
    shown.clear();
    page.checkButton()->click();
    ASSERT_TRUE(waitFor(shown));
    const CliResult cli = runCli({QStringLiteral("health"), bundle, QStringLiteral("--run"),
                                  QStringLiteral("S1"), QStringLiteral("--redundant"),
                                  QStringLiteral("T_ambient=T_bed"), QStringLiteral("--json")});
    ASSERT_EQ(cli.exitCode, 0) << cli.err.constData();
    std::map<QString, std::pair<double, double>> found;
    for (const QJsonValue& c : QJsonDocument::fromJson(cli.out)
                                   .object()[QStringLiteral("runs")][0][QStringLiteral("channels")]
                                   .toArray())
        for (const QJsonValue& f : c[QStringLiteral("findings")].toArray()) {
            EXPECT_EQ(f[QStringLiteral("kind")].toString(), QStringLiteral("redundant_drift"));
            const QJsonArray range = f[QStringLiteral("ranges_s")][0].toArray();
            found[c[QStringLiteral("id")].toString()] = {range[0].toDouble(), range[1].toDouble()};
        }
    ASSERT_EQ(found.size(), 2u) << cli.out.constData();
    ASSERT_EQ(page.flagModel()->rowCount(), 2);
    for (int row = 0; row < 2; ++row) {
        const auto at = [&](int column, int role = Qt::UserRole) {
            return page.flagModel()->data(page.flagModel()->index(row, column), role);
        };
        const QString channel = at(FlagModel::Channel, Qt::DisplayRole).toString();
        ASSERT_TRUE(found.count(channel)) << qPrintable(channel);
        EXPECT_EQ(at(FlagModel::Kind).toString(), QStringLiteral("redundant_drift"));
        EXPECT_EQ(at(FlagModel::From).toDouble(), found[channel].first);
        EXPECT_EQ(at(FlagModel::To).toDouble(), found[channel].second);
        // The drift is past 0.5 K only after 6000 s.
        EXPECT_GT(found[channel].first, 6000);
    }
}

TEST(DriftHealthPages, fitTheSmallestSupportedWindow) {
    // 1280 × 800 with the campaign tree beside them leaves the pages about 1000 px.
    ui::MainWindow window;
    EXPECT_LE(window.iso230_3Page()->minimumSizeHint().width(), 1000);
    EXPECT_LE(window.sensorHealthPage()->minimumSizeHint().width(), 1000);
}
