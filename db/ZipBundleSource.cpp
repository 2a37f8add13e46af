#include "db/ZipBundleSource.h"

#include <quazip.h>
#include <quazipfile.h>
#include <QFile>
#include <QFileInfo>
#include <QSet>

#include "core/bundle/RegularFile.h"

namespace driftlab::db {
namespace {

const QString kCampaignFile = QStringLiteral("campaign.json");

class ZipBundleSource : public bundle::BundleSource {
public:
    ZipBundleSource(const QString& path, const QString& prefix, const QStringList& entries)
        : m_path(path), m_prefix(prefix) {
        for (const QString& entry : entries) m_entries.insert(entry);
    }
    QString location() const override { return m_path; }
    bool contains(const QString& fileName) const override {
        return m_entries.contains(m_prefix + fileName);
    }
    std::unique_ptr<QIODevice> open(const QString& fileName, QString* error) const override {
        if (!contains(fileName)) {
            *error = QStringLiteral("not in the archive");
            return nullptr;
        }
        // Each entry gets its own QuaZip handle, so several can be open at once.
        auto file = std::make_unique<QuaZipFile>(m_path, m_prefix + fileName, QuaZip::csSensitive);
        if (!file->open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("cannot unzip (zip error %1)").arg(file->getZipError());
            return nullptr;
        }
        return file;
    }
    QString displayPath(const QString& fileName) const override {
        return m_path + QLatin1Char('/') + m_prefix + fileName;
    }

private:
    QString m_path;
    QString m_prefix;  ///< "" or "folder/" inside the archive
    QSet<QString> m_entries;
};

bool looksLikeZip(const QString& path) {
    QString ignored;  // a file that cannot be read is not taken for an archive
    const auto file = bundle::openRegularFile(path, &ignored);
    return file && file->read(4) == QByteArrayLiteral("PK\x03\x04");
}

}  // namespace

std::unique_ptr<bundle::BundleSource> openBundleSource(const QString& path, QString* error) {
    const QFileInfo info(path);
    if (info.isDir() || !info.exists()) return bundle::openBundleFolder(path, error);
    if (const QString kind = bundle::irregularFileKind(path); !kind.isEmpty()) {
        *error = kind + QStringLiteral(", not a bundle folder or .zip archive");
        return nullptr;
    }
    if (!looksLikeZip(path)) {
        *error = QStringLiteral("not a bundle folder or .zip archive");
        return nullptr;
    }
    QuaZip zip(path);
    if (!zip.open(QuaZip::mdUnzip)) {
        *error =
            QStringLiteral("cannot open the zip archive (zip error %1)").arg(zip.getZipError());
        return nullptr;
    }
    const QStringList entries = zip.getFileNameList();
    QStringList prefixes;
    for (const QString& entry : entries) {
        if (entry.startsWith(QLatin1String("__MACOSX/"))) continue;  // Finder's resource forks
        if (entry == kCampaignFile)
            prefixes << QString();
        else if (entry.endsWith(QLatin1Char('/') + kCampaignFile) &&
                 entry.count(QLatin1Char('/')) == 1)
            prefixes << entry.left(entry.size() - kCampaignFile.size());
    }
    if (prefixes.size() != 1) {
        *error = prefixes.isEmpty()
                     ? QStringLiteral(
                           "the zip archive holds no campaign.json (at its root or in "
                           "one folder)")
                     : QStringLiteral(
                           "the zip archive holds %1 bundles (%2); zip one bundle per "
                           "archive")
                           .arg(prefixes.size())
                           .arg(prefixes.join(QStringLiteral(", ")));
        return nullptr;
    }
    return std::make_unique<ZipBundleSource>(path, prefixes.front(), entries);
}

}  // namespace driftlab::db
