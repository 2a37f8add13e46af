#pragma once
// What a test measured, kept for docs/validation.md: one JSON object per
// record in the build's validation-records/<kind>/<name>.json, which
// tests/validation/validation_page.py turns into the validation page.

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace driftlab::test {

inline void writeValidationRecord(const QString& kind, const QString& name,
                                  const QJsonObject& record) {
    const QString directory = QStringLiteral(DRIFTLAB_VALIDATION_RECORDS "/") + kind;
    QDir().mkpath(directory);
    QFile file(QDir(directory).filePath(name + QStringLiteral(".json")));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        << qPrintable(file.fileName());
    file.write(QJsonDocument(record).toJson());
}

}  // namespace driftlab::test
