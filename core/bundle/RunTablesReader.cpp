// motion.csv and positioning.csv: the motion programme actually run and the
// interferometer's readings (docs/bundles.md), read before samples.csv.

#include <algorithm>
#include <cmath>

#include "core/bundle/BundleParser.h"
#include "core/bundle/SampleRows.h"
#include "core/bundle/ValueLimits.h"
#include "core/domain/MessageText.h"

namespace driftlab::bundle {
namespace {

/// Whether a moving run's readings, on the run's clock, have no cycle 0 and
/// begin with a whole pass of cycle 1 at its start, where docs/bundles.md puts
/// cycle 0. A run that lost its cold pass starts with cycle 1 later, warm.
bool firstPassIsCycleOneAtTheStart(const Run& run) {
    const auto& readings = run.positioning;
    const auto firstOther =
        std::find_if(readings.begin(), readings.end(), [](const auto& m) { return m.cycle != 1; });
    return !readings.empty() && readings.front().cycle == 1 &&
           readings.front().time_s <= kLoggerClockStart_s &&
           std::none_of(firstOther, readings.end(), [](const auto& m) { return m.cycle <= 1; });
}

}  // namespace

using namespace files;

/// The columns of a file of fixed format (motion.csv, positioning.csv), each
/// required. A further column (an interferometer package's air and material
/// temperatures, a comment) is merely unusual: ignored, with a warning.
std::vector<int> BundleParser::formatColumns(const CsvTable& csv, const QStringList& expected) {
    QStringList others;
    std::vector<int> indices = csv.requireColumns(expected, others);
    if (!others.isEmpty())
        warnings << QStringLiteral("%1:1: column(s) %2 not part of the format (%3): ignored")
                        .arg(csv.fileName(), quotedList(others), expected.join(QLatin1Char(',')));
    return indices;
}

void BundleParser::readMotion() {
    const auto table = openCsv(kMotion);
    CsvTable& csv = *table;
    const QStringList expected{QStringLiteral("run"),   QStringLiteral("start_s"),
                               QStringLiteral("end_s"), QStringLiteral("from_mm"),
                               QStringLiteral("to_mm"), QStringLiteral("feed_mm_min")};
    const std::vector<int> c = formatColumns(csv, expected);
    Overrun overrun;
    while (csv.next()) {
        const std::size_t r = runOf(csv, c[0]);
        Run& run = m_campaign.runs[r];
        MotionSegment m{csv.time(c[1]), csv.time(c[2]), csv.number(c[3]), csv.number(c[4]),
                        csv.number(c[5])};
        check(csv, c[1], impossibleClockTime(m.start_s));
        check(csv, c[2], impossibleClockTime(m.end_s));
        check(csv, c[5], impossibleAxisValue(kFeedColumn, m.feed_mm_min));
        if (m.end_s < m.start_s)
            csv.fail(c[2], QStringLiteral("segment ends (%1 s) before it starts (%2 s)")
                               .arg(numberText(m.end_s))
                               .arg(numberText(m.start_s)));
        if (!run.motion.empty() && m.start_s < run.motion.back().end_s)
            csv.fail(c[1], QStringLiteral("time goes backwards in run %1: segment starts at %2 s, "
                                          "before the previous one ends (%3 s)")
                               .arg(quotedText(run.id))
                               .arg(numberText(m.start_s))
                               .arg(numberText(run.motion.back().end_s)));
        checkPosition(csv, c[3], m.from_mm, overrun);
        checkPosition(csv, c[4], m.to_mm, overrun);
        run.motion.push_back(m);
        m_lastMotion[r] = {csv.line(), c[2] + 1};
    }
    warnOverrun(kMotion, overrun);
    reportProgress(csv, 0.0, 0.1);
}

void BundleParser::readPositioning() {
    const auto table = openCsv(kPositioning);
    CsvTable& csv = *table;
    const QStringList expected{QStringLiteral("run"),       QStringLiteral("time_s"),
                               QStringLiteral("cycle"),     QStringLiteral("target_mm"),
                               QStringLiteral("direction"), QStringLiteral("deviation_um")};
    const std::vector<int> c = formatColumns(csv, expected);
    Overrun overrun;
    QStringList otherSpellings;  // of a direction, as other software writes it
    int otherSpellingLine = 0;
    while (csv.next()) {
        const std::size_t r = runOf(csv, c[0]);
        Run& run = m_campaign.runs[r];
        PositioningMeasurement p;
        p.time_s = csv.time(c[1]);
        check(csv, c[1], impossibleClockTime(p.time_s));
        if (!run.positioning.empty() && p.time_s < run.positioning.back().time_s)
            csv.fail(c[1], QStringLiteral("time goes backwards in run %1 (%2 s after %3 s)")
                               .arg(quotedText(run.id))
                               .arg(numberText(p.time_s))
                               .arg(numberText(run.positioning.back().time_s)));
        p.cycle = csv.integer(c[2], 0);  // cycles count passes, from 0
        p.target_mm = csv.number(c[3]);
        checkPosition(csv, c[3], p.target_mm, overrun);
        const QString direction = csv.text(c[4]);
        const std::optional<Direction> d = directionFromText(direction);
        if (!d)
            csv.fail(c[4], QStringLiteral("direction must be + or -, found %1 (also read: "
                                          "↑ ↓, up down, pos neg, +1 -1)")
                               .arg(quotedCell(csv.field(c[4]))));
        p.direction = *d;
        if (direction != QLatin1String("+") && direction != QLatin1String("-") &&
            !otherSpellings.contains(direction)) {
            if (otherSpellings.isEmpty()) otherSpellingLine = csv.line();
            otherSpellings << direction;
        }
        p.deviation_um = csv.number(c[5]);
        check(csv, c[5], impossibleDeviation(p.deviation_um));
        run.positioning.push_back(p);
        m_lastPositioning[r] = {csv.line(), c[1] + 1};
    }
    warnOverrun(kPositioning, overrun);
    if (!otherSpellings.isEmpty())
        warnings << QStringLiteral(
                        "%1:%2: direction written as %3: read as + (positive, ↑) and "
                        "- (negative, ↓)")
                        .arg(kPositioning)
                        .arg(otherSpellingLine)
                        .arg(quotedList(otherSpellings));
    for (const Run& run : m_campaign.runs) {
        double largest_um = 0;
        for (const PositioningMeasurement& p : run.positioning)
            largest_um = std::max(largest_um, std::abs(p.deviation_um));
        if (const auto why =
                tinyMicrometres(run.positioning.size(), largest_um, QStringLiteral("deviations")))
            warnings
                << QStringLiteral("%1: run %2: %3").arg(kPositioning, quotedText(run.id), *why);
    }
    reportProgress(csv, 0.1, 0.1);
}

/// Motion and positioning times may be on a logger's clock until samples.csv
/// has set each run's clock (loggerClockOffset_s); on it, each must be a time
/// since the run's start. A run whose samples start at 0 s keeps its Unix
/// times in positioning.csv, and they are refused where they stand.
void BundleParser::checkRunClockTimes(const std::vector<std::optional<double>>& offset_s) const {
    const auto check = [&](const QString& file, const LastRecord& last, std::size_t r,
                           double time_s) {
        if (const auto why = impossibleTime(onRunClock(time_s, offset_s[r].value_or(0.0))))
            throw BundleException(
                {file, last.line, last.column,
                 QStringLiteral("run %1: %2").arg(quotedText(m_campaign.runs[r].id), *why)});
    };
    for (std::size_t r = 0; r < m_campaign.runs.size(); ++r) {
        const Run& run = m_campaign.runs[r];
        if (!run.motion.empty()) check(kMotion, m_lastMotion[r], r, run.motion.back().end_s);
        if (!run.positioning.empty())
            check(kPositioning, m_lastPositioning[r], r, run.positioning.back().time_s);
    }
}

/// Interferometer software often counts measurement cycles from 1. When no
/// moving run has a cycle 0 and each begins with a whole pass of cycle 1 at its
/// start, that pass is the cold reference: every cycle is counted one lower,
/// with a warning. ISO 230-2 positioning runs keep their numbers (they need no
/// reference). Called once the runs are on their own clocks.
void BundleParser::countCyclesFromZero() {
    QStringList runs;
    for (const Run& run : m_campaign.runs) {
        if (run.kind != RunKind::Moving || run.positioning.empty()) continue;
        if (!firstPassIsCycleOneAtTheStart(run)) return;
        runs << run.id;
    }
    if (runs.isEmpty()) return;
    for (Run& run : m_campaign.runs)
        if (run.kind == RunKind::Moving)
            for (PositioningMeasurement& m : run.positioning) --m.cycle;
    warnings << QStringLiteral(
                    "%1: the cycles of run(s) %2 are counted from 1, with no cycle 0: "
                    "their first pass, cycle 1, is read as the cold reference (cycle 0) "
                    "and every cycle is counted one lower")
                    .arg(kPositioning, quotedList(runs));
}

}  // namespace driftlab::bundle
