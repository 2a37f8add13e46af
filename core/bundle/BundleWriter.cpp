#include "core/bundle/BundleWriter.h"

#include <QDir>
#include <QJsonDocument>
#include <QSaveFile>
#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/bundle/CampaignJson.h"

namespace driftlab {
namespace {

void appendNumber(QByteArray& out, double value) {
    if (std::isnan(value)) return;  // missing sample: empty cell
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, end - buffer);
}

std::optional<BundleError> save(const QDir& dir, const QString& name, const QByteArray& content) {
    QSaveFile file(dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size() || !file.commit())
        return BundleError{name, 0, 0, QStringLiteral("cannot write: ") + file.errorString()};
    return std::nullopt;
}

QByteArray samplesCsv(const Campaign& c) {
    QByteArray out = "run,time_s";
    for (const QString& column : c.sample_columns) out += ',' + column.toUtf8();
    out += '\n';
    for (const Run& run : c.runs) {
        const QByteArray id = run.id.toUtf8();
        const SampleSeries& s = run.samples;
        for (std::size_t row = 0; row < s.rowCount(); ++row) {
            out += id;
            out += ',';
            appendNumber(out, s.time_s[row]);
            for (const auto& column : s.values) {
                out += ',';
                appendNumber(out, column[row]);
            }
            out += '\n';
        }
    }
    return out;
}

QByteArray motionCsv(const Campaign& c) {
    QByteArray out = "run,start_s,end_s,from_mm,to_mm,feed_mm_min\n";
    for (const Run& run : c.runs)
        for (const MotionSegment& m : run.motion) {
            out += run.id.toUtf8();
            for (double v : {m.start_s, m.end_s, m.from_mm, m.to_mm, m.feed_mm_min}) {
                out += ',';
                appendNumber(out, v);
            }
            out += '\n';
        }
    return out;
}

QByteArray positioningCsv(const Campaign& c) {
    QByteArray out = "run,time_s,cycle,target_mm,direction,deviation_um\n";
    for (const Run& run : c.runs)
        for (const PositioningMeasurement& p : run.positioning) {
            out += run.id.toUtf8() + ',';
            appendNumber(out, p.time_s);
            out += ',' + QByteArray::number(p.cycle) + ',';
            appendNumber(out, p.target_mm);
            out += p.direction == Direction::Positive ? ",+," : ",-,";
            appendNumber(out, p.deviation_um);
            out += '\n';
        }
    return out;
}

}  // namespace

std::optional<BundleError> writeBundle(const Campaign& campaign, const QString& directory) {
    QDir dir(directory);
    if (!dir.mkpath(QStringLiteral(".")))
        return BundleError{directory, 0, 0, QStringLiteral("cannot create the bundle folder")};

    const bool hasMotion = std::any_of(campaign.runs.begin(), campaign.runs.end(),
                                       [](const Run& r) { return !r.motion.empty(); });
    const bool hasPositioning = std::any_of(campaign.runs.begin(), campaign.runs.end(),
                                            [](const Run& r) { return !r.positioning.empty(); });
    if (auto e = save(dir, QStringLiteral("campaign.json"),
                      QJsonDocument(campaignToJson(campaign)).toJson(QJsonDocument::Indented)))
        return e;
    if (auto e = save(dir, QStringLiteral("samples.csv"), samplesCsv(campaign))) return e;
    if (hasMotion)
        if (auto e = save(dir, QStringLiteral("motion.csv"), motionCsv(campaign))) return e;
    if (hasPositioning)
        if (auto e = save(dir, QStringLiteral("positioning.csv"), positioningCsv(campaign)))
            return e;
    return std::nullopt;
}

}  // namespace driftlab
