// driftlab-cli history on the lab's PostgreSQL store (docs/history.md,
// docs/lab-store.md): the campaigns of one machine axis, in the order of their
// dates, with the figures of iso230-2 on the same server. The real server of
// the test cluster (PgTestServer.h), real processes.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/postgres/PgTestServer.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// The example bundle named `name`, on `axis`, dated `date`, deviations times `scale`.
QString datedBundle(const QTemporaryDir& dir, const QString& name, const QByteArray& axis,
                    const QByteArray& date, double scale) {
    const QString bundle = dir.filePath(name);
    copyBundle(exampleBundlePath(), bundle);
    const QString json = bundle + QStringLiteral("/campaign.json");
    replaceInFile(json, "\"X axis moving-state example\"",
                  '"' + name.toUtf8() + "\", \"date\": \"" + date + '"');
    replaceInFile(json, "\"axis\": \"X\"", "\"axis\": \"" + axis + '"');
    rewriteColumn(bundle + QStringLiteral("/positioning.csv"), 5,
                  [scale](double v) { return QByteArray::number(v * scale, 'g', 17); });
    return bundle;
}

qint64 import(const QString& url, const QString& bundle) {
    const CliResult r = runCli({"import", bundle, "--db", url});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return r.out.trimmed().toLongLong();
}

}  // namespace

TEST(HistoryServer, listsTheAxisCampaignsOfAServerStoreByDate) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("history_store"));
    QTemporaryDir dir;
    const qint64 later = import(url, datedBundle(dir, "X after crash", "X", "2026-09-01", 2.0));
    const qint64 other = import(url, datedBundle(dir, "Y quarterly", "Y", "2026-01-01", 1.0));
    const qint64 earlier = import(url, datedBundle(dir, "X quarterly", "X", "2026-03-01", 1.0));

    const CliResult r =
        runCli({"history", "--db", url, "--machine", "VMC-850", "--axis", "X", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonArray campaigns = json(r)[QStringLiteral("campaigns")].toArray();
    ASSERT_EQ(campaigns.size(), 2) << r.out.constData();
    const qint64 order[] = {earlier, later};
    for (int i = 0; i < 2; ++i) {
        const QJsonObject c = campaigns[i].toObject();
        EXPECT_EQ(qint64(c["id"].toDouble()), order[i]);
        EXPECT_NE(qint64(c["id"].toDouble()), other);
        const CliResult iso =
            runCli({"iso230-2", "--db", url, "--campaign", QString::number(order[i]), "--json"});
        ASSERT_EQ(iso.exitCode, 0) << iso.err.constData();
        for (const char* f : {"A", "E", "R", "B", "M"})
            EXPECT_EQ(c["iso230_2"].toObject()[QLatin1String(f)].toDouble(),
                      json(iso)[QLatin1String(f)].toDouble())
                << f;
    }
    EXPECT_GT(campaigns[1].toObject()["change_from_first"].toObject()["A"].toDouble(), 0);

    const CliResult none = runCli({"history", "--db", url, "--machine", "VMC-850", "--axis", "Z"});
    EXPECT_EQ(none.exitCode, 1);
    EXPECT_TRUE(reason(none.err).contains("VMC-850 axis Y (1 campaign)")) << none.err.constData();
}
