#include "core/bundle/BundleSource.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>

#include "core/bundle/RegularFile.h"

namespace driftlab::bundle {
namespace {

class FolderBundleSource : public BundleSource {
public:
    explicit FolderBundleSource(const QString& path) : m_dir(path) {}
    QString location() const override { return m_dir.path(); }
    bool contains(const QString& fileName) const override { return m_dir.exists(fileName); }
    std::unique_ptr<QIODevice> open(const QString& fileName, QString* error) const override {
        return openRegularFile(m_dir.filePath(fileName), error);
    }
    QString displayPath(const QString& fileName) const override { return m_dir.filePath(fileName); }

private:
    QDir m_dir;
};

}  // namespace

std::unique_ptr<BundleSource> openBundleFolder(const QString& path, QString* error) {
    if (!QFileInfo(path).isDir()) {
        *error = QFileInfo::exists(path) ? QStringLiteral("not a bundle folder or .zip archive")
                                         : QStringLiteral("no such bundle folder or archive");
        return nullptr;
    }
    return std::make_unique<FolderBundleSource>(path);
}

QByteArray bundleContentSha256(const BundleSource& source, QString* error) {
    QCryptographicHash hash(QCryptographicHash::Sha256);
    QByteArray buffer(1 << 20, Qt::Uninitialized);
    for (const char* name : {"campaign.json", "samples.csv", "motion.csv", "positioning.csv"}) {
        const QString fileName = QString::fromLatin1(name);
        if (!source.contains(fileName)) continue;
        auto file = source.open(fileName, error);
        if (!file) return {};
        hash.addData(QByteArray(name) + '\0');
        qint64 size = 0, got;
        while ((got = file->read(buffer.data(), buffer.size())) > 0) {
            hash.addData(QByteArrayView(buffer.constData(), got));
            size += got;
        }
        if (got < 0) {
            *error = fileName + QStringLiteral(": ") + file->errorString();
            return {};
        }
        hash.addData(QByteArray::number(size) + '\0');
    }
    return hash.result().toHex();
}

}  // namespace driftlab::bundle
