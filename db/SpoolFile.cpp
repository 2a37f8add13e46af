#include "db/SpoolFile.h"

#include <QDir>
#include <QFileInfo>
#include <QSqlQuery>
#include <QStandardPaths>

#include "db/RunLogger.h"

namespace driftlab::db {

QString defaultSpoolPath(QString* error) {
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
                           QStringLiteral("/driftlab");
    if (!QDir().mkpath(folder)) {
        if (error) *error = QStringLiteral("%1: cannot create the spool's folder").arg(folder);
        return {};
    }
    return folder + QStringLiteral("/spool.sqlite");
}

std::optional<QString> prepareSpool(const QString& path, QString* error) {
    if (!QFileInfo::exists(path)) {
        auto created = CampaignStore::open(path, StoreAccess::CreateIfMissing, error);
        if (!created || !created->publish(error)) return std::nullopt;
    }
    auto spool = CampaignStore::open(path, StoreAccess::ReadWrite, error);
    if (!spool) return std::nullopt;
    return ensureSpoolId(*spool, error);
}

std::optional<SpoolState> spoolState(const QString& path, CampaignStore& server, QString* error) {
    if (!QFileInfo::exists(path)) {
        if (error) *error = QStringLiteral("%1: no such spool").arg(path);
        return std::nullopt;
    }
    auto spool = CampaignStore::open(path, StoreAccess::ReadOnly, error);
    if (!spool) return std::nullopt;
    const QString id = spoolId(*spool);
    SpoolState state;
    QSqlQuery runs(spool->database());
    if (!runs.exec(QStringLiteral("SELECT id, status FROM run ORDER BY id"))) {
        if (error) *error = QStringLiteral("%1: the spool's runs cannot be read").arg(path);
        return std::nullopt;
    }
    while (runs.next()) {
        ++state.runs;
        state.logging += runs.value(1).toString() == QLatin1String("logging");
        // A spool without an id was never uploaded from.
        if (id.isEmpty() ||
            !uploadedId(server, id, QStringLiteral("run"), runs.value(0).toLongLong()))
            ++state.pending;
    }
    return state;
}

std::optional<UploadReport> syncSpool(const QString& path, CampaignStore& server, QString* error) {
    if (!QFileInfo::exists(path)) {
        if (error) *error = QStringLiteral("%1: no such spool").arg(path);
        return std::nullopt;
    }
    const auto id = prepareSpool(path, error);
    if (!id) return std::nullopt;
    {
        auto writable = CampaignStore::open(path, StoreAccess::ReadWrite, error);
        if (!writable) return std::nullopt;
        markInterruptedRuns(*writable, error);
    }
    auto source = CampaignStore::open(path, StoreAccess::ReadOnly, error);
    if (!source) return std::nullopt;
    return uploadSpool(*source, *id, server, error);
}

}  // namespace driftlab::db
