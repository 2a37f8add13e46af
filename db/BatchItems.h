#pragma once
// The items of a batch (docs/batch.md): the paths given, turned into one item
// per campaign — a bundle folder, a zipped bundle, each campaign of a
// DriftLab store (FILE#ID) — with folders that are none of these searched
// for them. Shared by `driftlab-cli batch` and the GUI.

#include <QString>
#include <QStringList>
#include <vector>

namespace driftlab::db {

struct BatchItem {
    QString item;      ///< as reported: the path, or FILE#ID for a campaign of a store
    QString path;      ///< the bundle (folder or .zip), or the store file
    QString campaign;  ///< the campaign's id in the store as given; empty for a bundle
    QString error;     ///< set: the item failed before it could be analysed (e.g. no such path)
};

struct FoundItems {
    std::vector<BatchItem> items;  ///< in the order of the PATHs; a folder's found items by path
    QStringList notes;             ///< files a search passed over, and why (for stderr)
};

/// The items of `paths`, each path being a bundle folder, a .zip bundle, a
/// store file (every campaign in it), FILE#ID (one campaign of a store), or a
/// folder searched recursively for those (a bundle folder is not searched
/// inside). A path that does not exist, a store that cannot be read or a
/// folder with nothing in it is an item with its error, not an exception.
FoundItems findBatchItems(const QStringList& paths);

}  // namespace driftlab::db
