#pragma once
// Conversions between domain values and SQL values shared by import and load.

#include <QJsonDocument>
#include <QJsonObject>
#include <QVariant>
#include <optional>

namespace driftlab::db {

inline QVariant toSql(const std::optional<double>& v) {
    return v ? QVariant(*v) : QVariant(QMetaType(QMetaType::Double));
}
inline std::optional<double> optionalDouble(const QVariant& v) {
    return v.isNull() ? std::nullopt : std::optional<double>(v.toDouble());
}
/// Qt binds a null QString as SQL NULL; text columns here are NOT NULL.
inline QString text(const QString& s) {
    return s.isNull() ? QStringLiteral("") : s;
}
inline QString jsonText(const QJsonObject& o) {
    return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
}
inline QJsonObject jsonObject(const QVariant& v) {
    return QJsonDocument::fromJson(v.toString().toUtf8()).object();
}

}  // namespace driftlab::db
