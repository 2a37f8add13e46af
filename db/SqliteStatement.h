#pragma once
// A prepared statement on the sqlite3 handle under a Qt SQL connection, for the
// hot paths (bulk sample insert and load) where QVariant binding per value
// costs more than SQLite itself. Everything else goes through QSqlQuery.

#include <sqlite3.h>
#include <QSqlDatabase>
#include <QString>

namespace driftlab::db {

/// The sqlite3 handle of an open QSQLITE connection, or nullptr.
sqlite3* sqliteHandle(const QSqlDatabase& db);

class SqliteStatement {
public:
    SqliteStatement(sqlite3* handle, const char* sql);
    ~SqliteStatement();
    SqliteStatement(const SqliteStatement&) = delete;
    SqliteStatement& operator=(const SqliteStatement&) = delete;

    bool ok() const { return m_statement != nullptr; }
    QString error() const;
    sqlite3_stmt* get() const { return m_statement; }

    void bind(int index, qint64 value) { sqlite3_bind_int64(m_statement, index, value); }
    void bind(int index, double value) { sqlite3_bind_double(m_statement, index, value); }
    /// Runs an insert/update; resets for reuse. False on error (see error()).
    bool execute();
    /// Steps a select: true while there is a row.
    bool nextRow() { return sqlite3_step(m_statement) == SQLITE_ROW; }

private:
    sqlite3* m_handle;
    sqlite3_stmt* m_statement = nullptr;
};

}  // namespace driftlab::db
