// The machine history of a real SQLite store: three campaigns of one machine
// axis whose deviations grow from campaign to campaign, and one campaign of
// another axis that must stay out of it. Checked through db::machineHistory,
// through the real `driftlab-cli history`, against `iso230-2 --json` of each
// campaign, and in the report's PDF read back with pdftotext.
#include <gtest/gtest.h>

#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <cmath>
#include <memory>

#include "db/CampaignStore.h"
#include "db/MachineHistoryStore.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

constexpr int kDeviationColumn = 5;  // run,time_s,cycle,target_mm,direction,deviation_um

/// The example bundle renamed, on axis `axis`, with every deviation times
/// `scale` (an axis that wears) and `dateJson` inserted into campaign.json.
QString makeBundle(const QTemporaryDir& dir, const QString& name, const QByteArray& axis,
                   double scale, const QByteArray& campaignDate, const QByteArray& runDate) {
    const QString bundle = dir.filePath(name);
    copyBundle(exampleBundlePath(), bundle);
    const QString json = bundle + QStringLiteral("/campaign.json");
    replaceInFile(json, "\"X axis moving-state example\"", '"' + name.toUtf8() + '"');
    replaceInFile(json, "\"axis\": \"X\"", "\"axis\": \"" + axis + '"');
    if (!campaignDate.isEmpty())
        replaceInFile(json, "\"format\": \"driftlab.campaign/1\",",
                      "\"format\": \"driftlab.campaign/1\", \"date\": \"" + campaignDate + "\",");
    if (!runDate.isEmpty())
        replaceInFile(json, "\"id\": \"S1\",",
                      "\"id\": \"S1\", \"started_at\": \"" + runDate + "\",");
    rewriteColumn(bundle + QStringLiteral("/positioning.csv"), kDeviationColumn,
                  [scale](double v) { return QByteArray::number(v * scale, 'g', 17); });
    return bundle;
}

qint64 importInto(const QString& store, const QString& bundle) {
    const CliResult r = runCli({"import", bundle, "--db", store, "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    EXPECT_TRUE(o.contains(QStringLiteral("campaign"))) << r.out.constData();
    // The date keys are campaign.json's own: read without a word.
    for (const QJsonValue& w : o.value(QStringLiteral("warnings")).toArray())
        EXPECT_FALSE(w.toString().contains(QStringLiteral("date")) ||
                     w.toString().contains(QStringLiteral("started_at")))
            << qPrintable(w.toString());
    return qint64(o.value(QStringLiteral("campaign")).toDouble());
}

QJsonObject iso230_2Of(const QString& store, qint64 id) {
    const CliResult r =
        runCli({"iso230-2", "--db", store, "--campaign", QString::number(id), "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return json(r);
}

const QStringList kFigures{"A", "E", "R", "B", "M"};

/// One store for every test of the file: built once, kept until the binary ends.
struct HistoryStore {
    QTemporaryDir dir;
    QString path;
    qint64 first = 0, second = 0, third = 0, otherAxis = 0;
    std::vector<double> scales{1.0, 1.4, 1.9};  ///< of first, second, third
};

const HistoryStore& historyStore() {
    static const std::unique_ptr<HistoryStore> made = [] {
        auto s = std::make_unique<HistoryStore>();
        s->path = s->dir.filePath(QStringLiteral("lab.sqlite"));
        // Imported out of date order, so that the store's ids do not give the
        // history's order: the second campaign first, the undated one last.
        const QString second = makeBundle(s->dir, QStringLiteral("X after re-compensation"), "X",
                                          s->scales[1], {}, "2026-04-05T08:00:00Z");
        const QString first = makeBundle(s->dir, QStringLiteral("X quarterly Q1"), "X",
                                         s->scales[0], "2026-01-12", {});
        const QString other =
            makeBundle(s->dir, QStringLiteral("Y quarterly Q1"), "Y", 3.0, "2026-02-01", {});
        const QString third =
            makeBundle(s->dir, QStringLiteral("X after crash"), "X", s->scales[2], {}, {});
        s->second = importInto(s->path, second);
        s->first = importInto(s->path, first);
        s->otherAxis = importInto(s->path, other);
        s->third = importInto(s->path, third);
        return s;
    }();
    return *made;
}

}  // namespace

TEST(MachineHistory, storeGivesTheAxisCampaignsByDateWithTheFiguresOfIso230_2) {
    const HistoryStore& s = historyStore();
    QString error;
    auto store = db::CampaignStore::open(s.path, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto h =
        db::machineHistory(*store, QStringLiteral("VMC-850"), QStringLiteral("X"), {}, &error);
    ASSERT_TRUE(h) << qPrintable(error);
    ASSERT_EQ(h->entries.size(), 3u);
    EXPECT_EQ(h->entries[0].campaign_id, s.first);
    EXPECT_EQ(h->entries[1].campaign_id, s.second);
    EXPECT_EQ(h->entries[2].campaign_id, s.third);
    EXPECT_EQ(h->entries[0].date.source, QStringLiteral("campaign.json date"));
    EXPECT_EQ(h->entries[0].date.utc.toString(Qt::ISODate), QStringLiteral("2026-01-12T00:00:00Z"));
    EXPECT_EQ(h->entries[1].date.source, QStringLiteral("run S1 started_at"));
    EXPECT_EQ(h->entries[2].date.source, QStringLiteral("import time"));
    EXPECT_EQ(h->find(s.otherAxis), nullptr);

    for (const history::HistoryEntry& e : h->entries) {
        const QJsonObject iso = iso230_2Of(s.path, e.campaign_id);
        EXPECT_EQ(e.positioning.run_id, QStringLiteral("S1"));
        EXPECT_DOUBLE_EQ(e.positioning.value_um(history::Figure::A), iso["A"].toDouble());
        EXPECT_DOUBLE_EQ(e.positioning.value_um(history::Figure::E), iso["E"].toDouble());
        EXPECT_DOUBLE_EQ(e.positioning.value_um(history::Figure::R), iso["R"].toDouble());
        EXPECT_DOUBLE_EQ(e.positioning.value_um(history::Figure::B), iso["B"].toDouble());
        EXPECT_DOUBLE_EQ(e.positioning.value_um(history::Figure::M), iso["M"].toDouble());
        EXPECT_TRUE(e.drift.determined()) << qPrintable(e.drift.not_determined);
    }
    // Every figure is linear in the deviations: it grows with their scale.
    for (std::size_t i = 1; i < 3; ++i) {
        const double a0 = h->entries[0].positioning.value_um(history::Figure::A);
        EXPECT_NEAR(h->entries[i].positioning.value_um(history::Figure::A), a0 * s.scales[i],
                    1e-9 * a0);
        EXPECT_NEAR(h->changeFromFirst_um(i, history::Figure::A), a0 * (s.scales[i] - 1),
                    1e-9 * a0);
        EXPECT_NEAR(h->changeFromPrevious_um(i, history::Figure::A),
                    a0 * (s.scales[i] - s.scales[i - 1]), 1e-9 * a0);
        EXPECT_NEAR(std::abs(h->entries[i].drift.max_drift_um),
                    std::abs(h->entries[0].drift.max_drift_um) * s.scales[i],
                    1e-6 * std::abs(h->entries[0].drift.max_drift_um));
    }
    EXPECT_TRUE(std::isnan(h->changeFromPrevious_um(0, history::Figure::A)));
    EXPECT_EQ(h->changeFromFirst_um(0, history::Figure::A), 0);
}

TEST(HistoryCli, jsonListsTheAxisCampaignsInTimeOrderWithIso230_2Figures) {
    const HistoryStore& s = historyStore();
    const CliResult r =
        runCli({"history", "--db", s.path, "--machine", "VMC-850", "--axis", "X", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject out = json(r);
    EXPECT_EQ(out["machine"].toString(), QStringLiteral("VMC-850"));
    EXPECT_EQ(out["axis"].toString(), QStringLiteral("X"));
    EXPECT_EQ(out["edition"].toInt(), 2014);
    EXPECT_EQ(out["coverage_factor"].toDouble(), 2);
    const QJsonArray campaigns = out["campaigns"].toArray();
    ASSERT_EQ(campaigns.size(), 3);
    const qint64 order[] = {s.first, s.second, s.third};
    QJsonObject firstIso;
    QJsonObject previousIso;
    for (int i = 0; i < 3; ++i) {
        const QJsonObject c = campaigns[i].toObject();
        EXPECT_EQ(qint64(c["id"].toDouble()), order[i]) << i;
        const QJsonObject iso = iso230_2Of(s.path, order[i]);
        if (i == 0) firstIso = iso;
        const QJsonObject figures = c["iso230_2"].toObject();
        EXPECT_EQ(figures["run"].toString(), QStringLiteral("S1"));
        for (const QString& f : kFigures) {
            EXPECT_EQ(figures[f].toDouble(), iso[f].toDouble()) << qPrintable(f) << " " << i;
            EXPECT_DOUBLE_EQ(c["change_from_first"].toObject()[f].toDouble(),
                             iso[f].toDouble() - firstIso[f].toDouble())
                << qPrintable(f);
            if (i == 0) {
                EXPECT_TRUE(c["change_from_previous"].toObject()[f].isNull());
            } else {
                EXPECT_DOUBLE_EQ(c["change_from_previous"].toObject()[f].toDouble(),
                                 iso[f].toDouble() - previousIso[f].toDouble())
                    << qPrintable(f);
            }
        }
        if (i > 0) {
            EXPECT_GT(figures["A"].toDouble(), previousIso["A"].toDouble()) << i;
        }
        previousIso = iso;
        const QJsonObject drift = c["iso230_3"].toObject();
        EXPECT_EQ(drift["run"].toString(), QStringLiteral("S1"));
        EXPECT_TRUE(drift["max_drift_um"].isDouble());
    }
    EXPECT_EQ(campaigns[0].toObject()["date"].toString(), QStringLiteral("2026-01-12T00:00:00Z"));
    EXPECT_EQ(campaigns[1].toObject()["date"].toString(), QStringLiteral("2026-04-05T08:00:00Z"));
    EXPECT_EQ(campaigns[2].toObject()["date_source"].toString(), QStringLiteral("import time"));
}

TEST(HistoryCli, drawsTheTrendAsPngAndPrintsTheTable) {
    const HistoryStore& s = historyStore();
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("trend.png"));
    const CliResult r =
        runCli({"history", "--db", s.path, "--machine", "VMC-850", "--axis", "Y", "--png", png});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = QString::fromUtf8(r.out);
    EXPECT_TRUE(text.contains(QStringLiteral("Machine history of VMC-850 axis Y: 1 campaign(s)")))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("Y quarterly Q1"))) << qPrintable(text);
    EXPECT_FALSE(text.contains(QStringLiteral("X quarterly Q1"))) << qPrintable(text);
    const QImage image(png);
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.width(), 960);
}

TEST(HistoryCli, anUnknownAxisIsRefusedNamingWhatTheStoreHolds) {
    const HistoryStore& s = historyStore();
    const CliResult r = runCli({"history", "--db", s.path, "--machine", "VMC-850", "--axis", "Z"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.out.isEmpty()) << r.out.constData();
    const QString why = QString::fromUtf8(reason(r.err));
    EXPECT_TRUE(why.contains(QStringLiteral("no campaign of machine 'VMC-850' axis 'Z'")))
        << qPrintable(why);
    EXPECT_TRUE(why.contains(QStringLiteral("VMC-850 axis X (3 campaigns)"))) << qPrintable(why);
    EXPECT_TRUE(why.contains(QStringLiteral("VMC-850 axis Y (1 campaign)"))) << qPrintable(why);
}

TEST(HistoryCli, missingMachineIsAUsageError) {
    const HistoryStore& s = historyStore();
    const CliResult r = runCli({"history", "--db", s.path, "--axis", "X"});
    EXPECT_EQ(r.exitCode, 2) << r.err.constData();
}

TEST(HistoryReport, pdfOfACampaignOfTheStoreShowsItsMachineHistoryInTimeOrder) {
    const HistoryStore& s = historyStore();
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const CliResult r =
        runCli({"report", "--db", s.path, "--campaign", QString::number(s.second), "--pdf", pdf});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = pdfText(pdf);
    const qsizetype section = text.indexOf(QStringLiteral("6 Machine history"));
    ASSERT_GE(section, 0) << qPrintable(text.right(3000));
    const QString history = text.mid(section);
    const qsizetype first = history.indexOf(QStringLiteral("X quarterly Q1"));
    const qsizetype second = history.indexOf(QStringLiteral("X after re-compensation *"));
    const qsizetype third = history.indexOf(QStringLiteral("X after crash"));
    EXPECT_GE(first, 0) << qPrintable(history);
    EXPECT_GT(second, first) << qPrintable(history);
    EXPECT_GT(third, second) << qPrintable(history);
    EXPECT_FALSE(history.contains(QStringLiteral("Y quarterly Q1"))) << qPrintable(history);
    // The printed A of each campaign is iso230-2's, to the table's 3 decimals.
    for (qint64 id : {s.first, s.second, s.third}) {
        const double a = iso230_2Of(s.path, id)["A"].toDouble();
        EXPECT_TRUE(history.contains(QString::number(a, 'f', 3)))
            << "A " << a << " of campaign " << id << " not in " << qPrintable(history);
    }
}

TEST(HistoryReport, aCampaignAloneOnItsAxisHasNoMachineHistorySection) {
    const HistoryStore& s = historyStore();
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const CliResult r = runCli(
        {"report", "--db", s.path, "--campaign", QString::number(s.otherAxis), "--pdf", pdf});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = pdfText(pdf);
    EXPECT_TRUE(text.contains(QStringLiteral("5 Pitch-error compensation")));
    EXPECT_FALSE(text.contains(QStringLiteral("Machine history"))) << qPrintable(text.right(2000));
}
