#include "db/BatchItems.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"

namespace driftlab::db {
namespace {

/// A folder with a campaign.json of any kind, or an export's staging folder:
/// a campaign.json that is not a regular file (a FIFO), and a staging folder,
/// are the bundle reader's to refuse, with its reason.
bool isBundleFolder(const QFileInfo& info) {
    const QDir folder(info.filePath());
    return info.isDir() && (QFileInfo::exists(folder.filePath(QStringLiteral("campaign.json"))) ||
                            folder.exists(bundle::kExportLockFile));
}

bool isZip(const QFileInfo& info) {
    return info.isFile() && info.suffix().compare(QLatin1String("zip"), Qt::CaseInsensitive) == 0;
}

/// Whether the file starts as every SQLite database does (the first 16 bytes
/// of its header); a store of any name (.sqlite, .db, .driftlab) is found so.
bool isSqliteFile(const QFileInfo& info) {
    QFile file(info.filePath());
    return info.isFile() && file.open(QIODevice::ReadOnly) &&
           file.read(16) == QByteArray("SQLite format 3\0", 16);
}

BatchItem failed(const QString& item, const QString& why) {
    return {item, {}, {}, QStringLiteral("%1: %2").arg(item, why)};
}

BatchItem bundle(const QString& path) {
    return {path, path, {}, {}};
}

BatchItem storeCampaign(const QString& store, const QString& id) {
    return {store + QLatin1Char('#') + id, store, id, {}};
}

/// Every campaign of a store, read with a read-only connection. Nullopt and
/// `why` when the file is not a DriftLab store or holds no campaign.
std::optional<std::vector<BatchItem>> storeItems(const QString& path, QString* why) {
    QString error;
    const auto store = CampaignStore::open(path, StoreAccess::ReadOnly, &error);
    if (!store) {
        // The store's own reasons start with the path already.
        *why = error.startsWith(path + QLatin1Char(':')) ? error.mid(path.size() + 2) : error;
        return std::nullopt;
    }
    std::vector<BatchItem> items;
    for (const CampaignSummary& c : store->listCampaigns())
        items.push_back(storeCampaign(path, QString::number(c.id)));
    if (items.empty()) {
        *why = QStringLiteral("a DriftLab store with no campaign in it");
        return std::nullopt;
    }
    return items;
}

/// Searches `folder` (not a bundle itself) in name order; bundle folders are
/// items and not searched inside, symbolic links to folders are not followed.
void search(const QString& folder, FoundItems& found) {
    const QFileInfoList entries =
        QDir(folder).entryInfoList(QDir::Dirs | QDir::Files | QDir::NoDotAndDotDot, QDir::Name);
    for (const QFileInfo& entry : entries) {
        const QString path = entry.filePath();
        if (isBundleFolder(entry))
            found.items.push_back(bundle(path));
        else if (entry.isDir() && !entry.isSymLink())
            search(path, found);
        else if (isZip(entry))
            found.items.push_back(bundle(path));
        else if (isSqliteFile(entry)) {
            QString why;
            if (auto items = storeItems(path, &why))
                found.items.insert(found.items.end(), items->begin(), items->end());
            else
                found.notes << QStringLiteral("%1: passed over: %2").arg(path, why);
        }
    }
}

void addPath(const QString& path, FoundItems& found) {
    const QFileInfo info(path);
    if (!info.exists()) {
        // FILE#ID: one campaign of a store (what batch reports, so it can be given again).
        const qsizetype hash = path.lastIndexOf(QLatin1Char('#'));
        bool numeric = false;
        if (hash > 0) path.mid(hash + 1).toLongLong(&numeric);
        if (numeric && QFileInfo(path.left(hash)).isFile())
            found.items.push_back(storeCampaign(path.left(hash), path.mid(hash + 1)));
        else
            found.items.push_back(failed(path, QStringLiteral("no such file or folder")));
        return;
    }
    if (isBundleFolder(info) || isZip(info)) {
        found.items.push_back(bundle(path));
        return;
    }
    if (info.isDir()) {
        const std::size_t before = found.items.size();
        search(path, found);
        if (found.items.size() == before)
            found.items.push_back(failed(path, QStringLiteral("no campaign bundle, zipped bundle "
                                                              "or DriftLab store in this folder")));
        return;
    }
    QString why =
        QStringLiteral("not a campaign bundle (folder or .zip) nor a DriftLab store (SQLite file)");
    if (isSqliteFile(info)) {
        if (auto items = storeItems(path, &why)) {
            found.items.insert(found.items.end(), items->begin(), items->end());
            return;
        }
    }
    found.items.push_back(failed(path, why));
}

}  // namespace

FoundItems findBatchItems(const QStringList& paths) {
    FoundItems found;
    for (const QString& path : paths) addPath(path, found);
    return found;
}

}  // namespace driftlab::db
