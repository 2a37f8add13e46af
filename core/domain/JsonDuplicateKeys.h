#pragma once
// A JSON object that names a key twice is ambiguous: QJsonDocument, like
// most parsers, keeps the last value without a word, so `{"cycles": 5, …,
// "cycles": 1}` would run one cycle. Files a user writes by hand are checked
// for it after they parse.

#include <QByteArray>
#include <QString>
#include <optional>

namespace driftlab {

struct DuplicateJsonKey {
    QString path;  ///< "procedure.positioning.cycles", from `root`
    int first_line = 0;
    int second_line = 0;
    QString toString() const;
};

/// The first key named twice in one object of `json` (valid JSON), or nullopt.
std::optional<DuplicateJsonKey> findDuplicateJsonKey(const QByteArray& json, const QString& root);

}  // namespace driftlab
