#include "core/domain/Run.h"

#include <QStringList>

#include <algorithm>
#include <cstring>

namespace driftlab {

QString toString(RunKind kind) {
    switch (kind) {
        case RunKind::Moving:
            return QStringLiteral("moving");
        case RunKind::Spindle:
            return QStringLiteral("spindle");
        case RunKind::Etve:
            return QStringLiteral("etve");
        case RunKind::Positioning:
            return QStringLiteral("positioning");
    }
    return {};
}

std::optional<RunKind> runKindFromString(const QString& text) {
    // In any case: "ETVE" is how the acronym is written by hand.
    for (RunKind kind : {RunKind::Moving, RunKind::Spindle, RunKind::Etve, RunKind::Positioning})
        if (toString(kind).compare(text.trimmed(), Qt::CaseInsensitive) == 0) return kind;
    return std::nullopt;
}

std::optional<Direction> directionFromText(const QString& text) {
    // '+' is the approach from below towards +x: ↑. A tool that swaps the two
    // swaps the sign of every ISO 230-2 B_i and exchanges R↑/R↓, E↑/E↓ and A↑/A↓.
    static const QStringList positive{QStringLiteral("+"),   QStringLiteral("+1"),
                                      QStringLiteral("↑"),   QStringLiteral("up"),
                                      QStringLiteral("pos"), QStringLiteral("positive")};
    static const QStringList negative{QStringLiteral("-"),       QStringLiteral("-1"),
                                      QStringLiteral("−"),       QStringLiteral("↓"),
                                      QStringLiteral("down"),    QStringLiteral("neg"),
                                      QStringLiteral("negative")};
    const QString t = text.trimmed().toLower();
    if (positive.contains(t)) return Direction::Positive;
    if (negative.contains(t)) return Direction::Negative;
    return std::nullopt;
}

bool isFeedAxisRun(RunKind kind) {
    return kind == RunKind::Moving || kind == RunKind::Positioning;
}

int SampleSeries::columnIndex(const QString& column) const {
    auto it = std::find(columns.begin(), columns.end(), column);
    return it == columns.end() ? -1 : int(it - columns.begin());
}

std::size_t SampleSeries::presentValueCount() const {
    std::size_t n = 0;
    for (const auto& column : values)
        n += std::count_if(column.begin(), column.end(), [](double v) { return !std::isnan(v); });
    return n;
}

bool SampleSeries::operator==(const SampleSeries& other) const {
    // Bitwise comparison so that two missing samples (NaN) compare equal.
    auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
        return a.size() == b.size() &&
               (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
    };
    if (!same(time_s, other.time_s) || columns != other.columns ||
        values.size() != other.values.size())
        return false;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!same(values[i], other.values[i])) return false;
    return true;
}

}  // namespace driftlab
