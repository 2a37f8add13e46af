#pragma once
// Bundles as users mail them: a zip archive (QuaZip), read entry by entry as
// a stream, never unpacked. The bundle's files may sit at the archive's root or
// in one folder inside it (what `zip -r bundle.zip bundle/` and the file
// managers' "compress" write).

#include <memory>

#include "core/bundle/BundleSource.h"

namespace driftlab::db {

/// A bundle folder or a .zip archive of one; nullptr with `error` set (the
/// path and why) when `path` is neither.
std::unique_ptr<bundle::BundleSource> openBundleSource(const QString& path, QString* error);

}  // namespace driftlab::db
