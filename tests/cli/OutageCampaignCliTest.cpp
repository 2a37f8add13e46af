// A campaign logged by DriftLab's own engine through a module outage, then
// used as a user would: `run --rig sim --outage S3@2800-3100` loses the
// temperature module for five minutes of S3's warm-up, over the interferometer
// pass at 2815–2905 s. Every model fits and names the hole, the diagnosis
// names it, compensate warns of it, the report says it; the store holds the
// hole in the temperature columns only and the event log the lost module.
#include <gtest/gtest.h>

#include <QFileInfo>
#include <QJsonArray>
#include <QSet>
#include <QSqlQuery>
#include <cmath>

#include "db/CampaignStore.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

constexpr double kFrom_s = 2800, kTo_s = 3100;
const QString kOutage = QStringLiteral("S3@2800-3100");
const QString kProcedure =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/procedures/moving-states-s1-s5.json");

/// The channels of the rig that warm with the screw across a five-minute
/// hole, and those that change slowly against it (the room, the air, the bed).
const QStringList kFast{"T_nut", "T_bearing_fixed", "T_bearing_free"};
const QStringList kSlow{"T_ambient", "T_air", "T_bed"};

struct LoggedCampaign {
    QString db;
    QString id;
};

/// The five moving states logged once per test binary through the outage.
const LoggedCampaign& campaignThroughOutage() {
    static QTemporaryDir dir;
    static const LoggedCampaign logged = [] {
        LoggedCampaign c{dir.filePath(QStringLiteral("lab.sqlite")), {}};
        const CliResult r = runCli(
            {"run", "--procedure", kProcedure, "--rig", "sim", "--outage", kOutage, "--db", c.db});
        EXPECT_EQ(r.exitCode, 0) << r.err.constData();
        c.id = QString::fromUtf8(r.out.trimmed());
        return c;
    }();
    return logged;
}

QStringList campaignArgs() {
    const LoggedCampaign& c = campaignThroughOutage();
    return {"--db", c.db, "--campaign", c.id};
}

Campaign loadCampaign() {
    const LoggedCampaign& c = campaignThroughOutage();
    QString error;
    auto store = db::CampaignStore::open(c.db, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    if (!store) return {};
    auto campaign = store->loadCampaign(c.id.toLongLong(), &error);
    EXPECT_TRUE(campaign) << error.toStdString();
    return campaign.value_or(Campaign{});
}

/// S3's interferometer readings inside the outage: what the fits must leave out.
std::size_t readingsInOutage() {
    const Campaign c = loadCampaign();
    const driftlab::Run* s3 = c.findRun(QStringLiteral("S3"));
    if (!s3) return 0;
    return std::size_t(std::count_if(
        s3->positioning.begin(), s3->positioning.end(),
        [](const PositioningMeasurement& p) { return p.time_s >= kFrom_s && p.time_s < kTo_s; }));
}

/// `gaps` of a JSON answer: one per temperature channel of S3, around the
/// outage (from the last sample before it; a flagged edge sample widens a
/// hole by its interval); the fast channels left out with the pass's
/// readings, the slow ones bridged.
void expectTheOutage(const QJsonArray& gaps, std::size_t readings) {
    const QString all = QString::fromUtf8(QJsonDocument(gaps).toJson(QJsonDocument::Compact));
    SCOPED_TRACE(all.toStdString());
    QSet<QString> channels;
    for (const QJsonValue& v : gaps) {
        const QJsonObject g = v.toObject();
        const QString channel = g["channel"].toString();
        SCOPED_TRACE(channel.toStdString());
        channels.insert(channel);
        EXPECT_EQ(g["run"].toString(), QStringLiteral("S3"));
        EXPECT_EQ(g["unit"].toString(), QStringLiteral("K"));
        EXPECT_LT(g["from_s"].toDouble(), kFrom_s);
        EXPECT_GE(g["from_s"].toDouble(), kFrom_s - 30);
        EXPECT_GE(g["to_s"].toDouble(), kTo_s);
        EXPECT_LE(g["to_s"].toDouble(), kTo_s + 30);
        if (kFast.contains(channel)) {
            EXPECT_EQ(g["treatment"].toString(), QStringLiteral("left_out"));
            EXPECT_EQ(g["observations_left_out"].toInteger(), qint64(readings));
            EXPECT_GT(g["bridge_error"].toDouble(), g["tolerance"].toDouble());
        } else {
            EXPECT_EQ(g["treatment"].toString(), QStringLiteral("bridged"));
            EXPECT_EQ(g["observations_left_out"].toInteger(), 0);
        }
    }
    EXPECT_EQ(channels, QSet<QString>(kFast.begin(), kFast.end()) +
                            QSet<QString>(kSlow.begin(), kSlow.end()));
    EXPECT_EQ(gaps.size(), kFast.size() + kSlow.size());
}

/// The line `fit`, `diagnose` and `compensate` print for the nut's hole (its
/// last sample before the outage is at 2790 s, its first after at 3100 s).
const QString kNutLine = QStringLiteral(
    "hole in the log left out: run 'S3', T_nut, 2790–3100 s (a straight bridge "
    "could miss the channel's course by");

}  // namespace

TEST(OutageCampaignCli, theStoreHoldsTheHoleInTheTemperatureColumnsAndTheLostModuleInTheLog) {
    const LoggedCampaign& logged = campaignThroughOutage();
    ASSERT_FALSE(logged.id.isEmpty());
    const Campaign c = loadCampaign();
    ASSERT_EQ(c.runs.size(), 5u);
    const driftlab::Run* s3 = c.findRun(QStringLiteral("S3"));
    ASSERT_NE(s3, nullptr);
    const SampleSeries& s = s3->samples;
    auto column = [&](const QString& id) -> const std::vector<double>& {
        return s.values[std::size_t(s.columnIndex(id))];
    };
    int lostRows = 0;
    for (std::size_t r = 0; r < s.rowCount(); ++r) {
        const double t = s.time_s[r];
        const bool lost = t >= kFrom_s && t < kTo_s;
        lostRows += lost;
        for (const QString& id : kFast + kSlow)
            ASSERT_EQ(std::isnan(column(id)[r]), lost) << id.toStdString() << " at " << t;
        for (const QString& id : {kPositionColumn, kFeedColumn, kTorqueColumn})
            ASSERT_TRUE(std::isfinite(column(id)[r])) << id.toStdString() << " at " << t;
    }
    EXPECT_EQ(lostRows, 30);  // 2800…3090 s at 10 s
    EXPECT_GT(readingsInOutage(), 0u);
    // The other runs have every temperature.
    for (const driftlab::Run& run : c.runs) {
        if (run.id == QLatin1String("S3")) continue;
        for (double v : run.samples.values[std::size_t(run.samples.columnIndex("T_nut"))])
            ASSERT_TRUE(std::isfinite(v)) << run.id.toStdString();
    }

    QString error;
    auto store = db::CampaignStore::open(logged.db, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << error.toStdString();
    QSqlQuery q(store->database());
    ASSERT_TRUE(q.exec(QStringLiteral("SELECT name || '=' || status FROM run ORDER BY id")));
    QStringList statuses;
    while (q.next()) statuses << q.value(0).toString();
    EXPECT_EQ(statuses, QStringList({"S1=complete", "S2=complete", "S3=complete", "S4=complete",
                                     "S5=complete"}));
    ASSERT_TRUE(q.exec(QStringLiteral(
        "SELECT r.name || ' ' || e.level || ' ' || e.source || ': ' || e.message FROM event_log e "
        "JOIN run r ON r.id = e.run_id WHERE e.source LIKE 'temperature module%' ORDER BY e.id")));
    QStringList events;
    while (q.next()) events << q.value(0).toString();
    EXPECT_EQ(events, QStringList({"S3 error temperature module sim: sim: the module does not "
                                   "answer (simulated outage)",
                                   "S3 warning temperature module sim: gap: no data from 2800 s "
                                   "to 3100 s (300 s); reconnected"}));
}

TEST(OutageCampaignCli, everyModelFitsThroughTheHoleAndNamesIt) {
    const std::size_t readings = readingsInOutage();
    ASSERT_GT(readings, 0u);
    for (const char* model : {"mlr", "poly-position", "exponential", "heat-transfer", "sensorless",
                              "arx", "arx-all", "auto"}) {
        SCOPED_TRACE(model);
        const CliResult r = runCli(
            QStringList{"fit"} + campaignArgs() +
            QStringList{"--model", model, "--train", "S1,S2", "--test", "S3,S4,S5", "--json"});
        ASSERT_EQ(r.exitCode, 0) << r.err.constData();
        const QJsonObject answer = json(r);
        EXPECT_EQ(answer["score_kind"].toString(), QStringLiteral("held_out"));
        EXPECT_TRUE(std::isfinite(answer["score"]["rms_um"].toDouble(qQNaN())));
        expectTheOutage(answer["gaps"].toArray(), readings);
    }
}

TEST(OutageCampaignCli, theDiagnosisNamesTheHole) {
    const CliResult r = runCli(QStringList{"diagnose"} + campaignArgs() + QStringList{"--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject answer = json(r);
    EXPECT_FALSE(answer["verdict"].toString().isEmpty());
    expectTheOutage(answer["gaps"].toArray(), readingsInOutage());
}

TEST(OutageCampaignCli, compensateWarnsOfTheHole) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("table.csv"));
    // S3 at the end of its warm-up needs more than the default limits (a
    // 25 µm step at 350 mm, 119 µm at 419 mm), with or without the outage.
    const CliResult r =
        runCli(QStringList{"compensate"} + campaignArgs() +
               QStringList{"--run", "S1", "--format", "csv", "--out", out, "--model",
                           "heat-transfer", "--train", "S1,S2", "--at", "S3@7200", "--max-value-um",
                           "300", "--max-step-um", "100"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(QFileInfo(out).size() > 0);
    const QString err = QString::fromUtf8(r.err);
    EXPECT_TRUE(err.contains(QStringLiteral("warning: ") + kNutLine)) << err.toStdString();
    EXPECT_TRUE(err.contains(QStringLiteral("warning: 3 hole(s) in the log bridged")))
        << err.toStdString();
}

TEST(OutageCampaignCli, theReportSaysTheHoleWhereItShowsTheFitsAndTheDiagnosis) {
    QTemporaryDir dir;
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const CliResult r =
        runCli(QStringList{"report"} + campaignArgs() + QStringList{"--run", "S1", "--pdf", pdf});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = pdfText(pdf, PdfText::ReadingOrder);
    // The model comparison and the diagnosis, each once.
    QString nut = kNutLine;
    nut[0] = nut[0].toUpper();
    EXPECT_EQ(text.count(nut), 2) << text.toStdString();
    EXPECT_EQ(text.count(QStringLiteral("3 hole(s) in the log bridged")), 2);
}

TEST(OutageCampaignCli, aBadOutageIsRefusedWithTheOptionAndTheValue) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("never.sqlite"));
    const std::pair<const char*, const char*> cases[] = {
        {"S3", "--outage: 'S3' is not RUN@FROM-TO"},
        {"S3@3300-3000", "--outage: 'S3@3300-3000': the outage must end after it starts"},
        {"S3@3000-3000", "--outage: 'S3@3000-3000': the outage must end after it starts"},
        {"S9@1-2", "--outage: 'S9@1-2': procedure 'Five moving states S1-S5' has no run 'S9'"},
        {"S3@20000-20100", "--outage: 'S3@20000-20100': run S3 ends at"}};
    for (const auto& [value, expected] : cases) {
        const CliResult r = runCli(
            {"run", "--procedure", kProcedure, "--rig", "sim", "--outage", value, "--db", db});
        EXPECT_EQ(r.exitCode, 2) << value;
        EXPECT_TRUE(reason(r.err).contains(expected)) << r.err.constData();
    }
    EXPECT_FALSE(QFileInfo::exists(db));
    const CliResult simulated = runCli({"simulate", "--out", dir.filePath(QStringLiteral("c")),
                                        "--runs", "S1,S2", "--outage", "S3@100-200"});
    EXPECT_EQ(simulated.exitCode, 2);
    EXPECT_TRUE(reason(simulated.err)
                    .contains("--outage: 'S3@100-200': the campaign has no run 'S3' (its runs: "
                              "S1, S2)"))
        << simulated.err.constData();
    const CliResult malformed =
        runCli({"simulate", "--out", dir.filePath(QStringLiteral("c")), "--outage", "S1@100..200"});
    EXPECT_EQ(malformed.exitCode, 2);
    EXPECT_TRUE(reason(malformed.err).contains("--outage: 'S1@100..200' is not RUN@FROM-TO"))
        << malformed.err.constData();
}
