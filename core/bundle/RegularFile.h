#pragma once
// Files the bundle reader and the store open are read whole, from disk. A FIFO
// would block the reader until some writer appeared (forever, for a user who
// made one by mistake), a device such as /dev/zero never ends, and a folder has
// no bytes: each is refused by name instead.

#include <QFile>
#include <QString>
#include <memory>

namespace driftlab::bundle {

/// What `path` is when it exists but is not a regular file ("a FIFO (named
/// pipe)", "a folder", "a character device", ...); empty for a regular file or
/// a missing path. Symbolic links are followed.
QString irregularFileKind(const QString& path);

/// `path` opened for reading if it is a regular file (checked on the opened
/// file, so it cannot be swapped between check and open, and without waiting
/// for a FIFO's writer); nullptr with `error` set otherwise, e.g. "a FIFO
/// (named pipe), not a regular file".
std::unique_ptr<QFile> openRegularFile(const QString& path, QString* error);

}  // namespace driftlab::bundle
