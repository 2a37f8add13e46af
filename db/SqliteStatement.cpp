#include "db/SqliteStatement.h"

#include <QSqlDriver>
#include <QVariant>

namespace driftlab::db {

sqlite3* sqliteHandle(const QSqlDatabase& db) {
    QVariant v = db.driver()->handle();
    if (!v.isValid() || qstrcmp(v.typeName(), "sqlite3*") != 0) return nullptr;
    return *static_cast<sqlite3* const*>(v.constData());
}

SqliteStatement::SqliteStatement(sqlite3* handle, const char* sql) : m_handle(handle) {
    if (handle && sqlite3_prepare_v2(handle, sql, -1, &m_statement, nullptr) != SQLITE_OK)
        m_statement = nullptr;
}

SqliteStatement::~SqliteStatement() {
    sqlite3_finalize(m_statement);
}

QString SqliteStatement::error() const {
    return m_handle ? QString::fromUtf8(sqlite3_errmsg(m_handle))
                    : QStringLiteral("no SQLite handle");
}

bool SqliteStatement::execute() {
    int rc = sqlite3_step(m_statement);
    sqlite3_reset(m_statement);
    return rc == SQLITE_DONE;
}

}  // namespace driftlab::db
