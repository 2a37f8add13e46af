#pragma once
// A bundle held in memory, for the fuzz targets: file name -> bytes.

#include <QBuffer>
#include <QHash>

#include "core/bundle/BundleSource.h"

namespace driftlab {

class MemoryBundleSource : public bundle::BundleSource {
public:
    void add(const QString& fileName, QByteArray bytes) { m_files.insert(fileName, bytes); }

    QString location() const override { return QStringLiteral("memory"); }
    bool contains(const QString& fileName) const override { return m_files.contains(fileName); }
    std::unique_ptr<QIODevice> open(const QString& fileName, QString* error) const override {
        auto it = m_files.find(fileName);
        if (it == m_files.end()) {
            *error = QStringLiteral("no such file");
            return nullptr;
        }
        auto buffer = std::make_unique<QBuffer>();
        buffer->setData(*it);
        buffer->open(QIODevice::ReadOnly);
        return buffer;
    }
    QString displayPath(const QString& fileName) const override {
        return QStringLiteral("memory/") + fileName;
    }

private:
    QHash<QString, QByteArray> m_files;
};

}  // namespace driftlab
