#include "core/rig/ModuleOutage.h"

#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>

namespace driftlab::rig {

std::optional<ModuleOutage> parseModuleOutage(const QString& text, QString* error) {
    static const QRegularExpression form(
        QStringLiteral(R"(^([A-Za-z0-9_]+)@(\d+(?:\.\d*)?)-(\d+(?:\.\d*)?)$)"));
    const QRegularExpressionMatch m = form.match(text.trimmed());
    if (!m.hasMatch()) {
        if (error)
            *error = QStringLiteral(
                         "'%1' is not RUN@FROM-TO (seconds of run time, e.g. "
                         "S3@3000-3300)")
                         .arg(text);
        return std::nullopt;
    }
    ModuleOutage outage{m.captured(1), m.captured(2).toDouble(), m.captured(3).toDouble()};
    if (!(outage.from_s < outage.to_s)) {
        if (error)
            *error = QStringLiteral(
                         "'%1': the outage must end after it starts (FROM %2 s, TO "
                         "%3 s)")
                         .arg(text)
                         .arg(outage.from_s)
                         .arg(outage.to_s);
        return std::nullopt;
    }
    return outage;
}

std::vector<ModuleOutage> outagesOf(const std::vector<ModuleOutage>& outages,
                                    const QString& run_id) {
    std::vector<ModuleOutage> mine;
    for (const ModuleOutage& o : outages)
        if (o.run_id == run_id) mine.push_back(o);
    std::sort(mine.begin(), mine.end(),
              [](const ModuleOutage& a, const ModuleOutage& b) { return a.from_s < b.from_s; });
    std::vector<ModuleOutage> merged;
    for (const ModuleOutage& o : mine) {
        if (!merged.empty() && o.from_s <= merged.back().to_s)
            merged.back().to_s = std::max(merged.back().to_s, o.to_s);
        else
            merged.push_back(o);
    }
    return merged;
}

bool moduleAnswers(const std::vector<ModuleOutage>& runOutages, double t_s) {
    return std::none_of(runOutages.begin(), runOutages.end(),
                        [&](const ModuleOutage& o) { return o.from_s <= t_s && t_s < o.to_s; });
}

std::vector<std::size_t> temperatureColumns(const std::vector<Channel>& channels,
                                            const std::vector<QString>& columns) {
    std::vector<std::size_t> out;
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (std::any_of(channels.begin(), channels.end(), [&](const Channel& ch) {
                return ch.id == columns[c] && ch.quantity == Quantity::Temperature;
            }))
            out.push_back(c);
    return out;
}

void blankOutages(const std::vector<ModuleOutage>& runOutages,
                  const std::vector<std::size_t>& temperature, SampleSeries& samples) {
    if (runOutages.empty()) return;
    for (std::size_t r = 0; r < samples.rowCount(); ++r)
        if (!moduleAnswers(runOutages, samples.time_s[r]))
            for (std::size_t c : temperature)
                samples.values[c][r] = std::numeric_limits<double>::quiet_NaN();
}

void blankOutages(const std::vector<ModuleOutage>& runOutages,
                  const std::vector<std::size_t>& temperature, std::size_t width, RunOutput& out,
                  std::size_t firstRow) {
    if (runOutages.empty()) return;
    for (std::size_t r = firstRow; r < out.time_s.size(); ++r)
        if (!moduleAnswers(runOutages, out.time_s[r]))
            for (std::size_t c : temperature)
                out.rows[r * width + c] = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace driftlab::rig
