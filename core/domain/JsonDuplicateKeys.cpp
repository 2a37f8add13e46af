#include "core/domain/JsonDuplicateKeys.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <vector>

namespace driftlab {
namespace {

/// An object or array being scanned.
struct Scope {
    bool object = false;
    QString path;
    QHash<QString, int> key_lines;  ///< objects: each key and the line it stands on
    bool expecting_key = true;      ///< objects: the next string is a key
    QString key;                    ///< objects: the key of the value being read
    int index = 0;                  ///< arrays: the element being read
};

/// A JSON string's text (from its opening to its closing quote) as its value.
QString decoded(const QByteArray& quoted) {
    if (!quoted.contains('\\')) return QString::fromUtf8(quoted.mid(1, quoted.size() - 2));
    return QJsonDocument::fromJson('[' + quoted + ']').array().first().toString();
}

QString childPath(const Scope& scope) {
    return scope.object ? scope.path + QLatin1Char('.') + scope.key
                        : scope.path + QStringLiteral("[%1]").arg(scope.index);
}

}  // namespace

QString DuplicateJsonKey::toString() const {
    return QStringLiteral("%1: named twice in one object (lines %2 and %3); only one may stand")
        .arg(path)
        .arg(first_line)
        .arg(second_line);
}

std::optional<DuplicateJsonKey> findDuplicateJsonKey(const QByteArray& json, const QString& root) {
    std::vector<Scope> scopes;
    int line = 1;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '\n') {
            ++line;
        } else if (c == '{' || c == '[') {
            const QString path = scopes.empty() ? root : childPath(scopes.back());
            scopes.push_back({c == '{', path, {}, true, {}, 0});
        } else if (c == '}' || c == ']') {
            if (!scopes.empty()) scopes.pop_back();
        } else if (c == ',' && !scopes.empty()) {
            Scope& s = scopes.back();
            s.expecting_key = s.object;
            ++s.index;
        } else if (c == ':' && !scopes.empty()) {
            scopes.back().expecting_key = false;
        } else if (c == '"') {
            const qsizetype start = i;
            for (++i; i < json.size() && json[i] != '"'; ++i)
                if (json[i] == '\\') ++i;
            if (scopes.empty() || !scopes.back().object || !scopes.back().expecting_key) continue;
            Scope& s = scopes.back();
            s.key = decoded(json.mid(start, i - start + 1));
            const auto seen = s.key_lines.constFind(s.key);
            if (seen != s.key_lines.constEnd()) return DuplicateJsonKey{childPath(s), *seen, line};
            s.key_lines.insert(s.key, line);
        }
    }
    return std::nullopt;
}

}  // namespace driftlab
