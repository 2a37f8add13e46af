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
    /// A BLOB that must stay valid until the statement runs (no copy is made).
    void bind(int index, const void* data, std::size_t bytes) {
        sqlite3_bind_blob64(m_statement, index, data, bytes, SQLITE_STATIC);
    }
    /// Runs an insert/update; resets for reuse. False on error (see error()).
    bool execute();
    /// Steps a select: true while there is a row; after the last row, failed()
    /// tells an error from the end of the rows.
    bool nextRow() {
        m_lastStep = sqlite3_step(m_statement);
        return m_lastStep == SQLITE_ROW;
    }
    bool failed() const { return m_lastStep != SQLITE_ROW && m_lastStep != SQLITE_DONE; }
    /// Makes a select run again (with new bindings).
    void reset() { sqlite3_reset(m_statement); }

private:
    sqlite3* m_handle;
    sqlite3_stmt* m_statement = nullptr;
    int m_lastStep = SQLITE_DONE;
};

}  // namespace driftlab::db
