#pragma once
// Where a bundle's files come from: a folder, or (db/ZipBundleSource) a zip
// archive. The reader asks for files by name and streams them, so neither
// form is unpacked onto disk or into memory.

#include <QIODevice>
#include <QString>
#include <memory>

namespace driftlab::bundle {

class BundleSource {
public:
    virtual ~BundleSource() = default;
    /// The folder or archive path, for messages.
    virtual QString location() const = 0;
    virtual bool contains(const QString& fileName) const = 0;
    /// The file opened for reading, or nullptr with `error` set.
    virtual std::unique_ptr<QIODevice> open(const QString& fileName, QString* error) const = 0;
    /// A path to show for one of the bundle's files ("bundle/samples.csv").
    virtual QString displayPath(const QString& fileName) const = 0;
};

/// A bundle folder on disk; nullptr with `error` set when `path` is not a folder.
std::unique_ptr<BundleSource> openBundleFolder(const QString& path, QString* error);

/// SHA-256 (hex) of a bundle's content: each present bundle file's name, size
/// and bytes in a fixed order, the same for a folder and a zip of it. Empty
/// with `error` set when a file cannot be read.
QByteArray bundleContentSha256(const BundleSource& source, QString* error);

}  // namespace driftlab::bundle
