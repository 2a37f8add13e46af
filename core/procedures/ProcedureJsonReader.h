#pragma once
// Reading one object of a procedure file with every failure naming its key
// path ("procedure.positioning.cycles: must be at least 1, got 0"). Internal
// to parseProcedure(): a failure is thrown as ProcedureError and caught there.

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include "core/domain/Run.h"

namespace driftlab::procedures {

/// The first thing wrong with a procedure, key path first.
struct ProcedureError {
    QString message;
};

/// How a JSON value is described in an error: `"abc" (a string)`, `2.5`, `an object`.
QString describeJsonValue(const QJsonValue& value);

/// The keys of one JSON object at a key path. The constructor refuses a key
/// not in `known` (a typo must not be silently ignored); each reader leaves
/// `value` (the struct default) when the key is missing, reads it when
/// present, and checks the result either way.
class ObjectReader {
public:
    ObjectReader(const QJsonObject& object, QString path, const QStringList& known);

    QString pathOf(const QString& key) const { return m_path + QLatin1Char('.') + key; }
    [[noreturn]] void fail(const QString& key, const QString& why) const;
    bool has(const QString& key) const { return m_object.contains(key); }

    void number(const QString& key, double& value);  ///< finite
    /// Finite, > 0 and at most `at_most`.
    void positive(const QString& key, double& value, double at_most);
    /// Finite, ≥ 0 and at most `at_most`.
    void nonNegative(const QString& key, double& value, double at_most);
    /// Finite, > 0 and in [lowest, highest].
    void positiveIn(const QString& key, double& value, double lowest, double highest);
    /// An integer in [lowest, highest].
    void integerIn(const QString& key, int& value, int lowest, int highest);
    void seed(const QString& key, unsigned& value);  ///< integer in 0 … 2^32 − 1
    void string(const QString& key, QString& value, bool required = false);
    void runId(const QString& key, QString& value);  ///< [A-Za-z0-9_]+
    /// [from, to] with to > from, inside `within` when given.
    void range(const QString& key, RangeMm& value, const RangeMm* within = nullptr);
    /// One of `choices`, returned as its index; `index` is the default.
    void choice(const QString& key, int& index, const QStringList& choices, bool required = false);
    QJsonObject object(const QString& key) const;  ///< empty when missing
    QJsonArray array(const QString& key) const;    ///< empty when missing

private:
    QJsonValue numberValue(const QString& key) const;
    [[noreturn]] void failAbove(const QString& key, double value, double at_most) const;

    QJsonObject m_object;  // a copy (implicitly shared), so a temporary can be read
    QString m_path;
};

}  // namespace driftlab::procedures
