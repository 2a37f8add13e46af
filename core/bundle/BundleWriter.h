#pragma once
// Writes a campaign bundle folder that BundleReader reads back identically.

#include <QString>
#include <optional>

#include "core/bundle/BundleError.h"
#include "core/domain/Campaign.h"

namespace driftlab::bundle {

/// The lock file an export holds in its staging folder (`DIR.partial-XXXXXX`,
/// beside the target) while it writes: the reader refuses a folder holding it,
/// and the next export to the same target removes the folder once the lock's
/// owner is gone (an export that was killed).
inline const QString kExportLockFile = QStringLiteral(".driftlab-export.lock");

/// What to do when the target folder already holds files.
enum class ExistingBundle {
    Refuse,   ///< only a new or empty folder is written
    Replace,  ///< a folder holding only a bundle's files is replaced as a whole
};

/// Writes campaign.json, samples.csv and, where the campaign has such data,
/// motion.csv and positioning.csv into `directory`. Numbers are written in
/// their shortest exact form, so reading gives the same doubles. The bundle is
/// written beside the target and renamed into place, so the folder holds a
/// complete bundle or is left as it was, never a mix of two campaigns; the
/// staging folders of killed exports to the same target are removed first.
std::optional<BundleError> writeBundle(const Campaign& campaign, const QString& directory,
                                       ExistingBundle existing = ExistingBundle::Refuse);

}  // namespace driftlab::bundle
