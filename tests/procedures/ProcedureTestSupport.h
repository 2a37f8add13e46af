#pragma once
// Shared by the procedure tests: the shipped files and small JSON edits.

#include <QDir>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include "core/procedures/Procedure.h"

namespace driftlab::procedures::test {

inline QString procedureDir() {
    return QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/procedures");
}

inline QString shippedPath(const char* file) {
    return procedureDir() + QLatin1Char('/') + QLatin1String(file);
}

/// The shipped procedure, which must load.
inline Procedure shipped(const char* file) {
    QString error;
    auto p = loadProcedureFile(shippedPath(file), &error);
    if (!p) throw std::runtime_error(error.toStdString());
    return *p;
}

/// `json` with the value at `path` (object keys) replaced; an undefined value removes the key.
inline QJsonObject withValue(QJsonObject json, QStringList path, const QJsonValue& value) {
    const QString key = path.takeFirst();
    if (!path.isEmpty())
        json[key] = withValue(json.value(key).toObject(), path, value);
    else if (value.isUndefined())
        json.remove(key);
    else
        json[key] = value;
    return json;
}

}  // namespace driftlab::procedures::test
