#pragma once
// Shared by the store and CLI tests of store safety: files of other
// applications, stores as earlier builds left them, and what a folder holds.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>

namespace driftlab::test {

/// Runs statements on a plain QSQLITE connection, no DriftLab code involved.
inline void rawSql(const QString& path, const QStringList& statements) {
    const QString name = QStringLiteral("raw-") + path;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        ASSERT_TRUE(db.open()) << qPrintable(db.lastError().text());
        QSqlQuery q(db);
        for (const QString& sql : statements)
            ASSERT_TRUE(q.exec(sql)) << qPrintable(sql) << ": " << qPrintable(q.lastError().text());
    }
    QSqlDatabase::removeDatabase(name);
}

/// Another application's database: rollback journal, its own tables and rows.
inline void writeForeignDatabase(const QString& path, quint32 applicationId,
                                 const QStringList& tables) {
    QStringList sql{QStringLiteral("PRAGMA journal_mode = DELETE"),
                    QStringLiteral("PRAGMA application_id = %1").arg(qint32(applicationId))};
    for (const QString& table : tables)
        sql << QStringLiteral("CREATE TABLE %1 (id INTEGER PRIMARY KEY, text TEXT)").arg(table)
            << QStringLiteral("INSERT INTO %1 (text) VALUES ('not yours')").arg(table);
    rawSql(path, sql);
}

/// Turns a store into one as the builds before application_id left it:
/// application_id 0, WAL mode in the header.
inline void makeLegacyStore(const QString& path) {
    rawSql(path, {QStringLiteral("PRAGMA application_id = 0"),
                  QStringLiteral("PRAGMA journal_mode = WAL")});
}

inline QByteArray header(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.read(100) : QByteArray();
}

/// PRAGMA application_id as stored in the header (big-endian at offset 68).
inline quint32 headerApplicationId(const QString& path) {
    const QByteArray h = header(path);
    if (h.size() < 72) return 0;
    quint32 id = 0;
    for (int i = 68; i < 72; ++i) id = id << 8 | quint8(h[i]);
    return id;
}

/// 1: rollback journal, 2: WAL (header offset 18).
inline int headerJournalVersion(const QString& path) {
    const QByteArray h = header(path);
    return h.size() > 18 ? int(h[18]) : -1;
}

/// The -wal, -shm and -journal files beside `path` that exist.
inline QStringList sideFiles(const QString& path) {
    QStringList found;
    for (const char* suffix : {"-wal", "-shm", "-journal"})
        if (QFile::exists(path + QLatin1String(suffix))) found << QLatin1String(suffix);
    return found;
}

/// A transaction of another connection on a store, held until destroyed, as
/// another process's would be (to a driftlab-cli under test, the test is one):
/// `BEGIN IMMEDIATE` keeps writers out, `BEGIN EXCLUSIVE` readers too (in
/// rollback-journal mode, the mode a store rests in).
class HeldStoreLock {
public:
    HeldStoreLock(const QString& path, const QString& begin)
        : m_name(QStringLiteral("held-") + path) {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_name);
        db.setDatabaseName(path);
        locked = db.open() && QSqlQuery(db).exec(begin);
    }
    ~HeldStoreLock() {
        {
            QSqlDatabase db = QSqlDatabase::database(m_name);
            QSqlQuery(db).exec(QStringLiteral("ROLLBACK"));
            db.close();
        }
        QSqlDatabase::removeDatabase(m_name);
    }
    HeldStoreLock(const HeldStoreLock&) = delete;
    HeldStoreLock& operator=(const HeldStoreLock&) = delete;

    bool locked = false;

private:
    QString m_name;
};

/// Everything in a folder, hidden files included.
inline QStringList folderEntries(const QString& dir) {
    return QDir(dir).entryList(
        QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

}  // namespace driftlab::test
