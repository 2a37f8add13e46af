#pragma once
// The campaign store: one SQLite file (WAL, foreign keys on) holding campaigns,
// their runs and data, and what DriftLab derives from them (DESIGN.md section 3).

#include <QSqlDatabase>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"

namespace driftlab::db {

struct CampaignSummary {
    qint64 id = 0;
    QString name;
    int runs = 0;
    qint64 samples = 0;  ///< present sample values over all runs and channels
};

class CampaignStore {
public:
    /// Opens or creates the database file and migrates it to the latest schema.
    /// Returns nullptr and sets `error` on failure.
    static std::unique_ptr<CampaignStore> open(const QString& path, QString* error);
    ~CampaignStore();
    CampaignStore(const CampaignStore&) = delete;
    CampaignStore& operator=(const CampaignStore&) = delete;

    /// Stores a whole campaign in one transaction: on any error (or when
    /// `progress` returns false) nothing is stored. Returns the campaign id.
    std::optional<qint64> importCampaign(const Campaign& campaign, QString* error,
                                         const std::function<bool(double)>& progress = {});
    /// Reads a campaign back exactly as it was imported.
    std::optional<Campaign> loadCampaign(qint64 id, QString* error) const;
    std::vector<CampaignSummary> listCampaigns() const;

    QSqlDatabase& database() { return m_db; }
    QString path() const { return m_db.databaseName(); }

private:
    explicit CampaignStore(QSqlDatabase db) : m_db(std::move(db)) {}
    QSqlDatabase m_db;
};

}  // namespace driftlab::db
