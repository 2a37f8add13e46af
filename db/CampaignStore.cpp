#include "db/CampaignStore.h"

#include <QAtomicInteger>
#include <QSqlError>
#include <QSqlQuery>

#include "db/SchemaMigrations.h"
#include "db/SqlValues.h"
#include "db/SqliteStatement.h"

namespace driftlab::db {
namespace {

QString nextConnectionName() {
    static QAtomicInteger<int> counter;
    return QStringLiteral("driftlab-store-%1").arg(counter.fetchAndAddRelaxed(1));
}

}  // namespace

std::unique_ptr<CampaignStore> CampaignStore::open(const QString& path, QString* error) {
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), nextConnectionName());
    db.setDatabaseName(path);
    db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=5000"));
    auto fail = [&](const QString& why) -> std::unique_ptr<CampaignStore> {
        *error = QStringLiteral("%1: %2").arg(path, why);
        QString name = db.connectionName();
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(name);
        return nullptr;
    };
    if (!db.open()) return fail(db.lastError().text());
    QSqlQuery q(db);
    // WAL: readers never block the logger; NORMAL sync in WAL mode keeps the file
    // consistent on power loss and loses at most the last committed transactions.
    for (const char* pragma :
         {"PRAGMA foreign_keys = ON", "PRAGMA journal_mode = WAL", "PRAGMA synchronous = NORMAL"})
        if (!q.exec(QString::fromLatin1(pragma)))
            return fail(
                QStringLiteral("not a usable SQLite database (%1)").arg(q.lastError().text()));
    QString migrationError;
    if (!migrate(db, &migrationError)) return fail(migrationError);
    return std::unique_ptr<CampaignStore>(new CampaignStore(db));
}

CampaignStore::~CampaignStore() {
    QString name = m_db.connectionName();
    m_db.close();
    m_db = QSqlDatabase();
    QSqlDatabase::removeDatabase(name);
}

std::vector<CampaignSummary> CampaignStore::listCampaigns() const {
    std::vector<CampaignSummary> out;
    QSqlQuery q(m_db);
    q.exec(QStringLiteral(
        "SELECT c.id, c.name, (SELECT count(*) FROM run r WHERE r.campaign_id = c.id), "
        "(SELECT coalesce(sum(b.present_count), 0) FROM sample_block b JOIN run r ON b.run_id = "
        "r.id "
        "WHERE r.campaign_id = c.id) "
        "FROM campaign c ORDER BY c.id"));
    while (q.next())
        out.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toInt(),
                       q.value(3).toLongLong()});
    return out;
}

}  // namespace driftlab::db
