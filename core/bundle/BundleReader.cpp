#include "core/bundle/BundleReader.h"

#include <QDateTime>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/bundle/BundleParser.h"
#include "core/bundle/BundleWriter.h"
#include "core/bundle/CampaignJson.h"
#include "core/bundle/ColumnSpelling.h"
#include "core/bundle/SampleRows.h"
#include "core/bundle/ValueLimits.h"
#include "core/domain/MessageText.h"

namespace driftlab::bundle {

using namespace files;

Campaign BundleParser::parse() {
    // An export's staging folder may already hold some files in their final
    // form; read as a bundle, it would lose what the export had yet to write.
    if (m_source.contains(kExportLockFile))
        throw BundleException(
            {kExportLockFile, 0, 0,
             QStringLiteral("the staging folder of an export that has not finished (killed, or "
                            "still writing), not a bundle; the next export to the same folder "
                            "removes a killed one")});
    QString error;
    auto json = m_source.open(kCampaign, &error);
    // A campaign.json that is there but cannot be read (a FIFO) is named as such;
    // without one, the folder may be something else than a bundle.
    if (!json)
        throw BundleException(
            {kCampaign, 0, 0,
             QStringLiteral("cannot open: %1%2")
                 .arg(error, m_source.contains(kCampaign)
                                 ? QString()
                                 : QStringLiteral(" (is this a campaign bundle?)"))});
    m_campaign = campaignFromJson(json->readAll(), kCampaign, &warnings);
    for (std::size_t i = 0; i < m_campaign.runs.size(); ++i)
        m_runIndex.insert(m_campaign.runs[i].id, int(i));
    setPositionLimits();
    m_lastMotion.assign(m_campaign.runs.size(), {});
    m_lastPositioning.assign(m_campaign.runs.size(), {});

    // Motion and positioning first (RunTablesReader.cpp): a run's first sample row then knows
    // whether every file of the run starts on a logger's clock.
    if (m_source.contains(kMotion)) readMotion();
    if (m_source.contains(kPositioning)) readPositioning();
    readSamples();
    countCyclesFromZero();
    if (m_options.progress) m_options.progress(1.0);
    return std::move(m_campaign);
}

std::unique_ptr<CsvTable> BundleParser::openCsv(const QString& name) {
    QString error;
    auto device = m_source.open(name, &error);
    if (!device) throw BundleException({name, 0, 0, QStringLiteral("cannot open: ") + error});
    auto csv = std::make_unique<CsvTable>(std::move(device), name);
    if (const QString note = csv->formatNote(); !note.isEmpty())
        warnings << name + QStringLiteral(": ") + note;
    return csv;
}

std::size_t BundleParser::runOf(const CsvTable& csv, int column) {
    auto it = m_runIndex.find(csv.text(column));
    if (it == m_runIndex.end())
        csv.fail(column, QStringLiteral("unknown run id %1 (not in campaign.json)")
                             .arg(quotedCell(csv.field(column))));
    return std::size_t(*it);
}

/// The nut's centre can be anywhere on the screw; further than half a nut
/// past either end it would be off the screw: a unit mix-up (µm for mm).
void BundleParser::setPositionLimits() {
    const auto& c = m_campaign;
    if (c.screw) {
        const double margin = c.nut_length_mm.value_or(0.0) / 2;
        m_positionMin_mm = c.screw->fixed_end_mm - margin;
        m_positionMax_mm = c.screw->fixed_end_mm + c.screw->length_mm + margin;
    } else if (c.travel_mm) {
        const double span = c.travel_mm->to_mm - c.travel_mm->from_mm;
        m_positionMin_mm = c.travel_mm->from_mm - span;
        m_positionMax_mm = c.travel_mm->to_mm + span;
    }
}

void BundleParser::checkPosition(const CsvTable& csv, int column, double position_mm,
                                 Overrun& overrun) {
    if (position_mm < m_positionMin_mm || position_mm > m_positionMax_mm)
        csv.fail(column, QStringLiteral("%1 = %2 mm lies beyond the screw [%3, %4] mm "
                                        "(unit mix-up? positions are in mm)")
                             .arg(shownText(csv.header()[std::size_t(column)]))
                             .arg(numberText(position_mm))
                             .arg(numberText(m_positionMin_mm))
                             .arg(numberText(m_positionMax_mm)));
    const auto& travel = m_campaign.travel_mm;
    if (!travel) return;
    const double outside = std::max(travel->from_mm - position_mm, position_mm - travel->to_mm);
    if (outside <= 0) return;
    if (overrun.count++ == 0) overrun.firstLine = csv.line();
    overrun.furthest_mm = std::max(overrun.furthest_mm, outside);
}

void BundleParser::warnOverrun(const QString& file, const Overrun& overrun) {
    if (overrun.count == 0) return;
    warnings << QStringLiteral(
                    "%1:%2: %3 position(s) outside the travel [%4, %5] mm, up to "
                    "%6 mm past it (overrun to reverse; accepted)")
                    .arg(file)
                    .arg(overrun.firstLine)
                    .arg(overrun.count)
                    .arg(m_campaign.travel_mm->from_mm)
                    .arg(m_campaign.travel_mm->to_mm)
                    .arg(overrun.furthest_mm);
}

/// The declared channel of a samples.csv column, also under a header giving its unit
/// ("T_nut [°C]", "T_nut [°F]": `unit` converts its values); nullptr for an axis column
/// (also spelled "Position [mm]"); throws for anything else.
const Channel* BundleParser::sampleChannel(const CsvTable& csv, int column,
                                           UnitConversion* unit) const {
    *unit = {};
    const QString& header = csv.header()[std::size_t(column)];
    if (const Channel* channel = m_campaign.findChannel(header)) return channel;
    if (!axisColumnOf(header).isEmpty()) return nullptr;
    const std::optional<HeaderWithUnit> withUnit = splitHeaderUnit(header);
    const Channel* channel = withUnit ? m_campaign.findChannel(withUnit->id) : nullptr;
    if (!channel)
        throw BundleException({kSamples, 1, column + 1,
                               QStringLiteral("column %1 is not a channel declared in %2")
                                   .arg(quotedText(header), kCampaign)});
    QString why;
    const auto conversion = conversionToDriftLabUnit(channel->quantity, withUnit->unit, &why);
    if (!conversion)
        throw BundleException({kSamples, 1, column + 1,
                               QStringLiteral("column %1: %2").arg(quotedText(header), why)});
    *unit = *conversion;
    return channel;
}

/// The axis column (position_mm, feed_mm_min, torque_Nm) a samples.csv header
/// names, as the format spells it or as other software does; empty for none.
QString BundleParser::axisColumnOf(const QString& header) {
    for (const QString& axis : {kPositionColumn, kFeedColumn, kTorqueColumn})
        if (spellsColumn(header, axis)) return axis;
    return {};
}

void BundleParser::check(const CsvTable& csv, int column, const std::optional<QString>& why) {
    if (why) csv.fail(column, QStringLiteral("column %1: %2").arg(csv.columnName(column), *why));
}

void BundleParser::reportProgress(const CsvTable& csv, double begin, double span) {
    if (m_options.progress && !m_options.progress(begin + span * csv.progress()))
        throw BundleException({csv.fileName(), csv.line(), 0, QStringLiteral("import cancelled")});
}

void BundleParser::readSamples() {
    const auto table = openCsv(kSamples);
    CsvTable& csv = *table;
    const int runCol = csv.requireColumn(QStringLiteral("run"));
    const int timeCol = csv.requireColumn(QStringLiteral("time_s"));
    std::vector<int> dataCols;
    std::vector<const Channel*> channels;  // nullptr for axis columns
    std::vector<UnitConversion> units;     // a channel's values into DriftLab's unit
    for (std::size_t i = 0; i < csv.header().size(); ++i) {
        if (int(i) == runCol || int(i) == timeCol) continue;
        UnitConversion unit;
        const Channel* channel = sampleChannel(csv, int(i), &unit);
        if (!unit.isIdentity())
            warnings << QStringLiteral("%1: column '%2': read in %3, converted to %4")
                            .arg(kSamples, csv.header()[i], unit.from, unitOf(channel->quantity));
        const QString name = channel ? channel->id : axisColumnOf(csv.header()[i]);
        const auto& columns = m_campaign.sample_columns;
        if (std::find(columns.begin(), columns.end(), name) != columns.end())
            throw BundleException({kSamples, 1, int(i) + 1,
                                   QStringLiteral("column %1 is channel %2 again")
                                       .arg(csv.columnName(int(i)), quotedText(name))});
        dataCols.push_back(int(i));
        channels.push_back(channel);
        units.push_back(unit);
        m_campaign.sample_columns.push_back(name);
    }
    const int positionCol = csv.column(kPositionColumn);
    for (Run& run : m_campaign.runs) {
        run.samples.columns = m_campaign.sample_columns;
        run.samples.values.assign(dataCols.size(), {});
    }
    SampleRowSink* sink = m_options.sampleSink;
    if (sink) sink->begin(m_campaign);

    // Each run's latest row waits for a later time: a row at its time (two
    // devices logged at one instant, or the log written twice) is merged.
    std::vector<HeldRow> held(m_campaign.runs.size());
    std::vector<std::optional<double>> offset_s(held.size());  // set by a run's first row
    DisplacementExtents extents(held.size(), channels);
    const auto store = [&](std::size_t r) {
        HeldRow& h = held[r];
        if (!h.held) return;
        h.held = false;
        if (sink) return sink->row(r, h.time_s, h.values.data());
        SampleSeries& s = m_campaign.runs[r].samples;
        s.time_s.push_back(h.time_s);
        for (std::size_t k = 0; k < h.values.size(); ++k) s.values[k].push_back(h.values[k]);
    };
    int mergedRows = 0, firstMergedLine = 0;
    std::vector<double> row(dataCols.size());
    std::string lastRunId;  // rows come in long stretches of one run: skip the lookup
    std::size_t runIndex = 0;
    Overrun overrun;
    int emptyRows = 0, firstEmptyRowLine = 0;
    for (std::size_t n = 0; csv.next(); ++n) {
        const std::string_view id = csv.field(runCol);
        if (n == 0 || id != lastRunId) {
            runIndex = runOf(csv, runCol);
            lastRunId.assign(id);
        }
        const double raw_s = csv.time(timeCol);
        check(csv, timeCol, impossibleClockTime(raw_s));
        HeldRow& last = held[runIndex];
        if (!offset_s[runIndex])
            offset_s[runIndex] = loggerClockOffset_s(m_campaign.runs[runIndex], raw_s);
        const double t = onRunClock(raw_s, *offset_s[runIndex]);
        check(csv, timeCol, impossibleTime(t));
        if (t < last.time_s)
            csv.fail(timeCol, QStringLiteral("time goes backwards in run %1 (%2 s after %3 s)")
                                  .arg(quotedText(m_campaign.runs[runIndex].id))
                                  .arg(numberText(t))
                                  .arg(numberText(last.time_s)));
        bool anyValue = false;
        for (std::size_t k = 0; k < dataCols.size(); ++k) {
            const int column = dataCols[k];
            double v = csv.numberOrMissing(column);
            if (!std::isnan(v) && !units[k].isIdentity()) v = units[k].apply(v);
            row[k] = v;
            if (std::isnan(v)) continue;
            anyValue = true;
            if (const Channel* channel = channels[k]) {
                check(csv, column, impossibleValue(channel->quantity, v, channel->role));
                extents.add(runIndex, k, v);
            } else if (column == positionCol)
                checkPosition(csv, column, v, overrun);
            else
                check(csv, column, impossibleAxisValue(csv.header()[column], v));
        }
        // A row without any value carries nothing to store; say so instead of keeping it.
        if (!anyValue) {
            if (++emptyRows == 1) firstEmptyRowLine = csv.line();
            continue;
        }
        if (last.held && t == last.time_s) {
            mergeInto(last, row, csv, dataCols, m_campaign.runs[runIndex].id);
            if (++mergedRows == 1) firstMergedLine = csv.line();
            continue;
        }
        store(runIndex);
        last = {t, csv.line(), row, true};
        if ((n & 0xFFFF) == 0) reportProgress(csv, 0.2, 0.8);
    }
    for (std::size_t r = 0; r < held.size(); ++r) store(r);
    moveOntoRunClocks(offset_s);
    if (mergedRows > 0)
        warnings << QStringLiteral(
                        "%1:%2: %3 row(s) repeat the time of their run's row before "
                        "and were merged into it (one instant, logged twice)")
                        .arg(kSamples)
                        .arg(firstMergedLine)
                        .arg(mergedRows);
    if (emptyRows > 0)
        warnings << QStringLiteral("%1:%2: %3 row(s) without any value were skipped")
                        .arg(kSamples)
                        .arg(firstEmptyRowLine)
                        .arg(emptyRows);
    warnOverrun(kSamples, overrun);
    for (const QString& w : extents.warnings(m_campaign.runs))
        warnings << kSamples + QStringLiteral(": ") + w;
    warnNothingLogged(offset_s);
}

/// What campaign.json declares and no file fills: a channel without a column
/// (a writer that dropped or renamed it), a run without any record.
void BundleParser::warnNothingLogged(const std::vector<std::optional<double>>& firstRowSeen) {
    QStringList channels, runs;
    for (const Channel& channel : m_campaign.channels)
        if (std::find(m_campaign.sample_columns.begin(), m_campaign.sample_columns.end(),
                      channel.id) == m_campaign.sample_columns.end())
            channels << channel.id;
    for (std::size_t r = 0; r < m_campaign.runs.size(); ++r) {
        const Run& run = m_campaign.runs[r];
        if (!firstRowSeen[r] && run.positioning.empty() && run.motion.empty()) runs << run.id;
    }
    if (!channels.isEmpty())
        warnings << QStringLiteral("%1: no column for channel(s) %2 of %3: they carry no reading")
                        .arg(kSamples, quotedList(channels), kCampaign);
    if (!runs.isEmpty())
        warnings << QStringLiteral("run(s) %1 of %2 have no record in any file: no data")
                        .arg(quotedList(runs), kCampaign);
}

/// Runs logged on a logger's clock are counted from their first record,
/// with one warning naming them.
void BundleParser::moveOntoRunClocks(const std::vector<std::optional<double>>& offset_s) {
    checkRunClockTimes(offset_s);
    QStringList moved;
    for (std::size_t r = 0; r < offset_s.size(); ++r) {
        const double offset = offset_s[r].value_or(0.0);
        if (!offset) continue;
        moveOntoRunClock(m_campaign.runs[r], offset);
        moved << QStringLiteral("%1 at %2 s%3")
                     .arg(quotedText(m_campaign.runs[r].id), numberText(offset),
                          offset >= 1e9
                              ? QStringLiteral(" (the clock read %1)")
                                    .arg(QDateTime::fromSecsSinceEpoch(qint64(offset), Qt::UTC)
                                             .toString(Qt::ISODate))
                              : QString());
    }
    if (!moved.isEmpty())
        warnings << QStringLiteral(
                        "run(s) starting late in every file, as on a logger's clock: %1; "
                        "counted from their first record (time_s counts from a run's start)")
                        .arg(moved.join(QStringLiteral(", ")));
}

BundleReadResult readBundle(const BundleSource& source, const BundleReadOptions& options) {
    BundleReadResult result;
    BundleParser parser(source, options);
    try {
        result.campaign = parser.parse();
        result.warnings = parser.warnings;
    } catch (const BundleException& e) {
        result.error = e.error;
    }
    return result;
}

BundleReadResult readBundle(const QString& directory, const BundleReadOptions& options) {
    QString error;
    auto source = openBundleFolder(directory, &error);
    if (!source) {
        BundleReadResult result;
        result.error = BundleError{directory, 0, 0, error};
        return result;
    }
    return readBundle(*source, options);
}

}  // namespace driftlab::bundle
