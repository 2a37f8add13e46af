#include "core/bundle/BundleWriter.h"

#include <QDir>
#include <QJsonDocument>
#include <QLockFile>
#include <QSaveFile>
#include <QTemporaryDir>
#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/bundle/CampaignJson.h"

namespace driftlab::bundle {
namespace {

const QStringList kBundleFiles{QStringLiteral("campaign.json"), QStringLiteral("samples.csv"),
                               QStringLiteral("motion.csv"), QStringLiteral("positioning.csv")};

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

/// Removes the staging folders that exports to `target` left when they were
/// killed mid-write: those holding an export lock whose owner is gone (QLockFile
/// keeps the owner's pid and program). A folder whose lock a running export
/// holds, or without a lock (the previous bundle moved aside, or not an
/// export's), is left alone.
void sweepStagingOfKilledExports(const QFileInfo& target) {
    const QDir parent = target.absoluteDir();
    const QString prefix = target.fileName() + QStringLiteral(".partial-");
    for (const QString& name :
         parent.entryList(QDir::Dirs | QDir::Hidden | QDir::NoDotAndDotDot | QDir::NoSymLinks)) {
        QDir staged(parent.filePath(name));
        if (!name.startsWith(prefix) || !staged.exists(kExportLockFile)) continue;
        QLockFile lock(staged.filePath(kExportLockFile));
        lock.setStaleLockTime(0);  // a long export is no dead one: only a gone owner counts
        if (!lock.tryLock(0)) continue;
        lock.unlock();
        staged.removeRecursively();
    }
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

std::optional<BundleError> writeBundle(const Campaign& campaign, const QString& directory,
                                       ExistingBundle existing) {
    const QFileInfo target(directory);
    const QString targetPath = target.absoluteFilePath();
    auto fail = [&](const QString& why) { return BundleError{directory, 0, 0, why}; };
    const QStringList present =
        target.isDir()
            ? QDir(targetPath)
                  .entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden | QDir::System)
            : QStringList();
    if (target.exists() && !target.isDir())
        return fail(QStringLiteral("exists and is not a folder"));
    if (!present.isEmpty()) {
        if (existing == ExistingBundle::Refuse)
            return fail(QStringLiteral("is not empty (%1); a bundle is written only into a new or "
                                       "empty folder (--force replaces a previous bundle whole)")
                            .arg(present.join(QStringLiteral(", "))));
        QStringList foreign;
        for (const QString& name : present)
            if (!kBundleFiles.contains(name)) foreign << name;
        if (!foreign.isEmpty())
            return fail(QStringLiteral("holds files that are not a bundle's (%1): not replaced")
                            .arg(foreign.join(QStringLiteral(", "))));
    }
    if (!QDir().mkpath(target.absolutePath()))
        return fail(QStringLiteral("cannot create the parent folder"));

    // Written beside the target, on the same file system, so that the final
    // rename is atomic; the staging folder vanishes on any failure.
    sweepStagingOfKilledExports(target);
    QTemporaryDir staging(targetPath + QStringLiteral(".partial-XXXXXX"));
    if (!staging.isValid())
        return fail(QStringLiteral("cannot create a staging folder: ") + staging.errorString());
    const QDir dir(staging.path());
    // Held until the bundle is complete: a reader refuses the folder while it is
    // there, and should this process be killed, the next export removes the folder.
    QLockFile lock(dir.filePath(kExportLockFile));
    lock.setStaleLockTime(0);
    if (!lock.tryLock(0))
        return fail(QStringLiteral("cannot lock the staging folder %1").arg(staging.path()));
    const bool hasMotion = std::any_of(campaign.runs.begin(), campaign.runs.end(),
                                       [](const Run& r) { return !r.motion.empty(); });
    const bool hasPositioning = std::any_of(campaign.runs.begin(), campaign.runs.end(),
                                            [](const Run& r) { return !r.positioning.empty(); });
    auto prefixed = [&](BundleError e) {
        e.file = QDir(directory).filePath(e.file);
        return e;
    };
    if (auto e = save(dir, QStringLiteral("samples.csv"), samplesCsv(campaign)))
        return prefixed(*e);
    if (hasMotion)
        if (auto e = save(dir, QStringLiteral("motion.csv"), motionCsv(campaign)))
            return prefixed(*e);
    if (hasPositioning)
        if (auto e = save(dir, QStringLiteral("positioning.csv"), positioningCsv(campaign)))
            return prefixed(*e);
    // campaign.json last: until the bundle is complete the folder lacks the file
    // every reader opens first, so not even a reader that knows nothing of the
    // lock (an older build, another tool) takes a killed export's folder for one.
    if (auto e = save(dir, QStringLiteral("campaign.json"),
                      QJsonDocument(campaignToJson(campaign)).toJson(QJsonDocument::Indented)))
        return prefixed(*e);
    lock.unlock();

    // An empty target folder is removed so the staged one can take its name; a
    // previous bundle is moved aside first and deleted only once the new one is in place.
    QString previous;
    if (target.isDir()) {
        if (present.isEmpty()) {
            QDir().rmdir(targetPath);
        } else {
            previous = staging.path() + QStringLiteral(".previous");
            if (!QDir().rename(targetPath, previous))
                return fail(QStringLiteral("cannot move the previous bundle aside"));
        }
    }
    if (!QDir().rename(staging.path(), targetPath)) {
        if (!previous.isEmpty()) QDir().rename(previous, targetPath);
        return fail(QStringLiteral("cannot move the new bundle into place"));
    }
    staging.setAutoRemove(false);
    if (!previous.isEmpty()) QDir(previous).removeRecursively();
    return std::nullopt;
}

}  // namespace driftlab::bundle
