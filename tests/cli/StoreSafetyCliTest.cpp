// driftlab-cli and files that are not (yet) its stores: other applications'
// databases, missing paths, read-only media, stores of earlier builds; run as
// a user runs them, with the exit code, the one-line reason and the file's bytes.
#include <grp.h>
#include <gtest/gtest.h>
#include <pwd.h>
#include <unistd.h>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "db/CampaignStore.h"
#include "tests/db/StoreTestSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QString kNeverWrites =
    QStringLiteral("; DriftLab never writes into another application's database");

CliResult importInto(const QString& dbPath, const QString& bundle = exampleBundlePath()) {
    return runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), dbPath});
}

CliResult infoOf(const QString& dbPath, const QStringList& wrapper = {}) {
    return runCli({QStringLiteral("info"), QStringLiteral("--db"), dbPath,
                   QStringLiteral("--campaign"), QStringLiteral("1"), QStringLiteral("--json")},
                  wrapper);
}

QByteArray line(const char* command, const QString& path, const QString& why) {
    return QStringLiteral("driftlab-cli %1: %2: %3")
        .arg(QLatin1String(command), path, why)
        .toUtf8();
}

/// How to run the CLI so that file permissions apply: as it is when not root;
/// as nobody through setpriv or runuser when root (root ignores permissions).
std::optional<QStringList> unprivileged() {
    if (geteuid() != 0) return QStringList();
    if (!getpwnam("nobody")) return std::nullopt;
    const QString group =
        getgrnam("nogroup") ? QStringLiteral("nogroup") : QStringLiteral("nobody");
    if (const QString setpriv = QStandardPaths::findExecutable(QStringLiteral("setpriv"));
        !setpriv.isEmpty())
        return QStringList{setpriv, QStringLiteral("--reuid=nobody"),
                           QStringLiteral("--regid=") + group, QStringLiteral("--clear-groups")};
    if (const QString runuser = QStandardPaths::findExecutable(QStringLiteral("runuser"));
        !runuser.isEmpty())
        return QStringList{runuser, QStringLiteral("-u"), QStringLiteral("nobody"),
                           QStringLiteral("--")};
    return std::nullopt;
}

}  // namespace

TEST(StoreSafetyCli, importIntoAnotherApplicationsDatabaseIsRefusedAndLeavesItByteIdentical) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("other-app.sqlite"));
    writeForeignDatabase(path, 0, {QStringLiteral("notes"), QStringLiteral("tags")});
    ASSERT_EQ(headerJournalVersion(path), 1);
    const QByteArray before = sha256OfFile(path);
    const QString why = QStringLiteral(
        "not a DriftLab store (application_id 0x00000000, tables: "
        "notes, tags)");

    CliResult r = importInto(path);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.out.isEmpty()) << r.out.constData();
    EXPECT_EQ(reason(r.err), line("import", path, why + kNeverWrites));
    CliResult info = infoOf(path);
    EXPECT_EQ(info.exitCode, 1);
    EXPECT_EQ(reason(info.err), line("info", path, why));

    EXPECT_EQ(sha256OfFile(path), before);
    EXPECT_EQ(headerJournalVersion(path), 1) << "the journal mode was switched";
    EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
}

TEST(StoreSafetyCli, importIntoNonSqliteFileIsRefused) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("notes.txt"));
    writeFile(path, "shopping: screws, nuts, a dial gauge\n");
    CliResult r = importInto(path);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), line("import", path, QStringLiteral("not an SQLite database")));
    EXPECT_EQ(readFile(path), QByteArray("shopping: screws, nuts, a dial gauge\n"));
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("notes.txt")});
}

TEST(StoreSafetyCli, infoOnMissingStoreIsAnErrorAndCreatesNothing) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("typo.sqlite"));
    CliResult info = infoOf(path);
    EXPECT_EQ(info.exitCode, 1);
    EXPECT_EQ(reason(info.err), line("info", path, QStringLiteral("no such DriftLab store")));
    // fit stores its result, but only into an existing store.
    CliResult fit =
        runCli({QStringLiteral("fit"), QStringLiteral("--db"), path, QStringLiteral("--campaign"),
                QStringLiteral("1"), QStringLiteral("--model"), QStringLiteral("mlr")});
    EXPECT_EQ(fit.exitCode, 1);
    EXPECT_EQ(reason(fit.err), line("fit", path, QStringLiteral("no such DriftLab store")));
    EXPECT_TRUE(folderEntries(dir.path()).isEmpty())
        << qPrintable(folderEntries(dir.path()).join(' '));
}

TEST(StoreSafetyCli, refusedImportIntoNewPathLeavesNoFile) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("bad"));
    copyBundle(exampleBundlePath(), bundle);
    replaceInFile(QDir(bundle).filePath(QStringLiteral("samples.csv")), "\nS1,20,", "\nS1,20,warm");
    const QString path = dir.filePath(QStringLiteral("new.sqlite"));
    CliResult r = importInto(path, bundle);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(
        reason(r.err).startsWith("driftlab-cli import: " + bundle.toUtf8() + "/samples.csv:4:3"))
        << r.err.constData();
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("bad")});
}

TEST(StoreSafetyCli, readOnlyCommandsLeaveNoWalOrShm) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(importInto(path).exitCode, 0);
    const QByteArray before = sha256OfFile(path);
    const QStringList source{QStringLiteral("--db"), path, QStringLiteral("--campaign"),
                             QStringLiteral("1")};
    const QList<QStringList> commands{
        QStringList{QStringLiteral("info")} + source,
        QStringList{QStringLiteral("export")} + source +
            QStringList{QStringLiteral("--out"), dir.filePath(QStringLiteral("exported"))},
        QStringList{QStringLiteral("compare")} + source +
            QStringList{QStringLiteral("--models"), QStringLiteral("mlr")}};
    for (const QStringList& command : commands) {
        CliResult r = runCli(command);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(command.front()) << ": " << r.err.constData();
        EXPECT_EQ(sha256OfFile(path), before) << qPrintable(command.front());
        EXPECT_TRUE(sideFiles(path).isEmpty())
            << qPrintable(command.front()) << " left " << qPrintable(sideFiles(path).join(' '));
    }
}

TEST(StoreSafetyCli, storeOnReadOnlyMediaCanBeRead) {
    const std::optional<QStringList> asUser = unprivileged();
    if (!asUser)
        GTEST_SKIP() << "running as root without setpriv/runuser or a 'nobody' user: file "
                        "permissions cannot be made to apply";
    QTemporaryDir dir;
    const QString media = dir.filePath(QStringLiteral("media"));
    ASSERT_TRUE(QDir().mkpath(media));
    const QString store = QDir(media).filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(importInto(store).exitCode, 0);
    // A store left in WAL mode (by an earlier build, or copied while written):
    // without a -shm, SQLite can only read it immutable on read-only media.
    const QString wal = QDir(media).filePath(QStringLiteral("wal.sqlite"));
    ASSERT_TRUE(QFile::copy(store, wal));
    makeLegacyStore(wal);
    ASSERT_EQ(headerJournalVersion(wal), 2);

    const auto readOnly = QFile::ReadOwner | QFile::ReadGroup | QFile::ReadOther;
    const auto traversable = readOnly | QFile::ExeOwner | QFile::ExeGroup | QFile::ExeOther;
    ASSERT_TRUE(QFile::setPermissions(store, readOnly));
    ASSERT_TRUE(QFile::setPermissions(wal, readOnly));
    ASSERT_TRUE(QFile::setPermissions(media, traversable));
    ASSERT_TRUE(QFile::setPermissions(dir.path(), traversable | QFile::WriteOwner));
    const QByteArray storeBefore = sha256OfFile(store), walBefore = sha256OfFile(wal);
    if (runCli({QStringLiteral("--help")}, *asUser).exitCode != 0)
        GTEST_SKIP() << "the unprivileged user cannot run " << DRIFTLAB_CLI;

    for (const QString& path : {store, wal}) {
        CliResult r = infoOf(path, *asUser);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(path) << ": " << r.err.constData();
        EXPECT_EQ(QJsonDocument::fromJson(r.out).object()[QStringLiteral("runs")].toArray().size(),
                  2);
        EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
    }
    // Writing is refused with a reason, and changes nothing.
    CliResult import = runCli({QStringLiteral("import"), exampleBundlePath(),
                               QStringLiteral("--db"), store, QStringLiteral("--again")},
                              *asUser);
    EXPECT_EQ(import.exitCode, 1);
    EXPECT_EQ(reason(import.err),
              line("import", store,
                   QStringLiteral("cannot be written (no write permission, or read-only media)")));
    EXPECT_EQ(sha256OfFile(store), storeBefore);
    EXPECT_EQ(sha256OfFile(wal), walBefore);
    QFile::setPermissions(media, traversable | QFile::WriteOwner);  // so the folder can be removed
}

TEST(StoreSafetyCli, legacyStoreWithoutApplicationIdIsAcceptedAndStamped) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(importInto(path).exitCode, 0);
    makeLegacyStore(path);
    ASSERT_EQ(headerApplicationId(path), 0u);
    const QByteArray before = sha256OfFile(path);

    CliResult info = infoOf(path);
    EXPECT_EQ(info.exitCode, 0) << info.err.constData();
    EXPECT_EQ(sha256OfFile(path), before) << "reading stamps nothing";

    // The same bundle once more: --again, or its content hash would refuse it.
    CliResult r = runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"),
                          path, QStringLiteral("--again")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(r.out.trimmed(), QByteArray("2"));
    EXPECT_EQ(headerApplicationId(path), db::kStoreApplicationId);
    EXPECT_EQ(headerJournalVersion(path), 1);
    EXPECT_TRUE(sideFiles(path).isEmpty()) << qPrintable(sideFiles(path).join(' '));
}

TEST(StoreSafetyCli, applicationIdIsSetOnNewStore) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lab.sqlite"));
    CliResult r = importInto(path);
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(header(path).mid(68, 4), QByteArray("DRFT"));
    EXPECT_EQ(headerApplicationId(path), db::kStoreApplicationId);
    EXPECT_EQ(folderEntries(dir.path()), QStringList{QStringLiteral("lab.sqlite")});
}
