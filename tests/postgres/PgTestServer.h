#pragma once
// The throw-away PostgreSQL cluster of the ctest fixture pg_cluster
// (pg_test_cluster.sh): its URL, a fresh database per test, raw SQL on it,
// and a stop and start of the server for the restart test. When the fixture
// could not start a cluster, skipReason() says why and the tests skip.
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <QUrl>

namespace driftlab::test {

class PgTestServer {
public:
    static QString stateDir() { return QStringLiteral(DRIFTLAB_PG_STATE_DIR); }

    /// Why there is no test cluster; empty when there is one.
    static QString skipReason() {
        QFile skip(stateDir() + QStringLiteral("/skip"));
        if (skip.open(QIODevice::ReadOnly)) return QString::fromUtf8(skip.readAll()).trimmed();
        if (baseUrl().isEmpty())
            return QStringLiteral(
                       "no test cluster (%1/url missing; run the pg_cluster fixture, "
                       "e.g. ctest -R postgres)")
                .arg(stateDir());
        return {};
    }

    /// postgresql://driftlab@127.0.0.1:PORT
    static QString baseUrl() {
        QFile file(stateDir() + QStringLiteral("/url"));
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()).trimmed()
                                              : QString();
    }
    static QString url(const QString& database) { return baseUrl() + QLatin1Char('/') + database; }

    /// Statements on a plain QPSQL connection, no DriftLab code involved;
    /// `database` "postgres" is the server's maintenance database.
    static void rawSql(const QString& database, const QStringList& statements) {
        const QUrl u(baseUrl());
        const QString name = QStringLiteral("pg-raw-") + database;
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), name);
            db.setHostName(u.host());
            db.setPort(u.port());
            db.setUserName(u.userName());
            db.setDatabaseName(database);
            ASSERT_TRUE(db.open()) << qPrintable(db.lastError().text());
            QSqlQuery q(db);
            for (const QString& sql : statements)
                ASSERT_TRUE(q.exec(sql))
                    << qPrintable(sql) << ": " << qPrintable(q.lastError().text());
        }
        QSqlDatabase::removeDatabase(name);
    }

    /// A new empty database named `name` (dropped first if a test left one).
    static QString freshDatabase(const QString& name) {
        rawSql(QStringLiteral("postgres"),
               {QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(name),
                QStringLiteral("CREATE DATABASE %1").arg(name)});
        return url(name);
    }

    /// pg_ctl stop -m fast / start of the fixture's server.
    static bool stopServer() { return cluster(QStringLiteral("stop-server")); }
    static bool startServer() { return cluster(QStringLiteral("start-server")); }

private:
    static bool cluster(const QString& command) {
        return QProcess::execute(
                   QStringLiteral("bash"),
                   {QStringLiteral(DRIFTLAB_PG_CLUSTER_SCRIPT), command, stateDir()}) == 0;
    }
};

}  // namespace driftlab::test

/// Skips the test, with the reason, when there is no test cluster.
#define DRIFTLAB_REQUIRE_PG_CLUSTER()                                             \
    do {                                                                          \
        const QString why = driftlab::test::PgTestServer::skipReason();           \
        if (!why.isEmpty()) GTEST_SKIP() << "no PostgreSQL: " << qPrintable(why); \
    } while (false)
