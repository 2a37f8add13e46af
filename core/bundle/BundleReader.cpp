#include "core/bundle/BundleReader.h"

#include <QDir>
#include <QFile>
#include <QHash>
#include <algorithm>
#include <cmath>

#include "core/bundle/CampaignJson.h"
#include "core/bundle/CsvTable.h"

namespace driftlab {
namespace {

const QString kCampaignFile = QStringLiteral("campaign.json");
const QString kSamplesFile = QStringLiteral("samples.csv");
const QString kMotionFile = QStringLiteral("motion.csv");
const QString kPositioningFile = QStringLiteral("positioning.csv");

// Positions outside the travel by more than this are a unit mix-up, not noise.
constexpr double kTravelToleranceMm = 1.0;

class BundleParser {
public:
    BundleParser(const QString& directory, const BundleReadOptions& options)
        : m_dir(directory), m_options(options) {}

    Campaign parse() {
        QFile json(m_dir.filePath(kCampaignFile));
        if (!json.open(QIODevice::ReadOnly))
            throw BundleException(
                {kCampaignFile, 0, 0,
                 QStringLiteral("cannot open in '%1': %2").arg(m_dir.path(), json.errorString())});
        m_campaign = campaignFromJson(json.readAll(), kCampaignFile);
        for (std::size_t i = 0; i < m_campaign.runs.size(); ++i)
            m_runIndex.insert(m_campaign.runs[i].id, int(i));

        readSamples();
        if (m_dir.exists(kMotionFile)) readMotion();
        if (m_dir.exists(kPositioningFile)) readPositioning();
        checkTemperatureUnits();
        return std::move(m_campaign);
    }

    QStringList warnings;

private:
    Run& runOf(const CsvTable& csv, int column) {
        auto it = m_runIndex.find(csv.text(column));
        if (it == m_runIndex.end())
            csv.fail(
                column,
                QStringLiteral("unknown run id '%1' (not in campaign.json)").arg(csv.text(column)));
        return m_campaign.runs[std::size_t(*it)];
    }

    void checkInTravel(const CsvTable& csv, int column, double position_mm) {
        const auto& travel = m_campaign.travel_mm;
        if (travel && (position_mm < travel->from_mm - kTravelToleranceMm ||
                       position_mm > travel->to_mm + kTravelToleranceMm))
            csv.fail(column, QStringLiteral("%1 = %2 mm lies outside the travel [%3, %4] mm "
                                            "(unit mix-up? positions are in mm)")
                                 .arg(csv.header()[std::size_t(column)])
                                 .arg(position_mm)
                                 .arg(travel->from_mm)
                                 .arg(travel->to_mm));
    }

    void reportProgress(const CsvTable& csv, double begin, double span) {
        if (m_options.progress && !m_options.progress(begin + span * csv.progress()))
            throw BundleException(
                {csv.fileName(), csv.line(), 0, QStringLiteral("import cancelled")});
    }

    void readSamples() {
        CsvTable csv(m_dir.filePath(kSamplesFile), kSamplesFile);
        const int runCol = csv.requireColumn(QStringLiteral("run"));
        const int timeCol = csv.requireColumn(QStringLiteral("time_s"));
        const std::vector<int>& dataCols = m_sampleHeaderColumns;
        for (std::size_t i = 0; i < csv.header().size(); ++i) {
            const QString& name = csv.header()[i];
            if (int(i) == runCol || int(i) == timeCol) continue;
            if (!isAxisColumn(name) && !m_campaign.findChannel(name))
                throw BundleException({kSamplesFile, 1, int(i) + 1,
                                       QStringLiteral("column '%1' is not a channel declared in %2")
                                           .arg(name, kCampaignFile)});
            m_sampleHeaderColumns.push_back(int(i));
            m_campaign.sample_columns.push_back(name);
        }
        const int positionCol = csv.column(kPositionColumn);
        for (Run& run : m_campaign.runs) {
            run.samples.columns = m_campaign.sample_columns;
            run.samples.values.assign(dataCols.size(), {});
        }

        for (std::size_t row = 0; csv.next(); ++row) {
            Run& run = runOf(csv, runCol);
            SampleSeries& s = run.samples;
            double t = csv.number(timeCol);
            if (!s.time_s.empty() && t <= s.time_s.back())
                csv.fail(
                    timeCol,
                    QStringLiteral("time goes backwards or repeats in run '%1' (%2 s after %3 s)")
                        .arg(run.id)
                        .arg(t)
                        .arg(s.time_s.back()));
            bool anyValue = false;
            for (std::size_t k = 0; k < dataCols.size(); ++k) {
                double v = csv.numberOrMissing(dataCols[k]);
                if (dataCols[k] == positionCol && !std::isnan(v))
                    checkInTravel(csv, dataCols[k], v);
                anyValue = anyValue || !std::isnan(v);
                s.values[k].push_back(v);
            }
            // A row without any value carries nothing to store; say so instead of keeping it.
            if (!anyValue) {
                for (auto& column : s.values) column.pop_back();
                if (++m_emptyRows == 1) m_firstEmptyRowLine = csv.line();
                continue;
            }
            s.time_s.push_back(t);
            if ((row & 0xFFFF) == 0) reportProgress(csv, 0.0, 0.8);
        }
        if (m_emptyRows > 0)
            warnings << QStringLiteral("%1:%2: %3 row(s) without any value were skipped")
                            .arg(kSamplesFile)
                            .arg(m_firstEmptyRowLine)
                            .arg(m_emptyRows);
    }

    void readMotion() {
        CsvTable csv(m_dir.filePath(kMotionFile), kMotionFile);
        const QStringList expected{QStringLiteral("run"),   QStringLiteral("start_s"),
                                   QStringLiteral("end_s"), QStringLiteral("from_mm"),
                                   QStringLiteral("to_mm"), QStringLiteral("feed_mm_min")};
        const std::vector<int> c = requireExactly(csv, expected);
        while (csv.next()) {
            Run& run = runOf(csv, c[0]);
            MotionSegment m{csv.number(c[1]), csv.number(c[2]), csv.number(c[3]), csv.number(c[4]),
                            csv.number(c[5])};
            if (m.end_s < m.start_s)
                csv.fail(c[2], QStringLiteral("segment ends (%1 s) before it starts (%2 s)")
                                   .arg(m.end_s)
                                   .arg(m.start_s));
            if (!run.motion.empty() && m.start_s < run.motion.back().end_s)
                csv.fail(c[1],
                         QStringLiteral("time goes backwards in run '%1': segment starts at %2 s, "
                                        "before the previous one ends (%3 s)")
                             .arg(run.id)
                             .arg(m.start_s)
                             .arg(run.motion.back().end_s));
            checkInTravel(csv, c[3], m.from_mm);
            checkInTravel(csv, c[4], m.to_mm);
            run.motion.push_back(m);
        }
        reportProgress(csv, 0.8, 0.1);
    }

    void readPositioning() {
        CsvTable csv(m_dir.filePath(kPositioningFile), kPositioningFile);
        const QStringList expected{QStringLiteral("run"),       QStringLiteral("time_s"),
                                   QStringLiteral("cycle"),     QStringLiteral("target_mm"),
                                   QStringLiteral("direction"), QStringLiteral("deviation_um")};
        const std::vector<int> c = requireExactly(csv, expected);
        while (csv.next()) {
            Run& run = runOf(csv, c[0]);
            PositioningMeasurement p;
            p.time_s = csv.number(c[1]);
            if (!run.positioning.empty() && p.time_s < run.positioning.back().time_s)
                csv.fail(c[1], QStringLiteral("time goes backwards in run '%1' (%2 s after %3 s)")
                                   .arg(run.id)
                                   .arg(p.time_s)
                                   .arg(run.positioning.back().time_s));
            p.cycle = csv.integer(c[2]);
            if (p.cycle < 0) csv.fail(c[2], QStringLiteral("cycle must not be negative"));
            p.target_mm = csv.number(c[3]);
            checkInTravel(csv, c[3], p.target_mm);
            QString direction = csv.text(c[4]);
            if (direction == QLatin1String("+"))
                p.direction = Direction::Positive;
            else if (direction == QLatin1String("-"))
                p.direction = Direction::Negative;
            else
                csv.fail(c[4],
                         QStringLiteral("direction must be + or -, found '%1'").arg(direction));
            p.deviation_um = csv.number(c[5]);
            run.positioning.push_back(p);
        }
        reportProgress(csv, 0.9, 0.1);
    }

    /// The file must have exactly these columns (any order); returns their indices.
    static std::vector<int> requireExactly(const CsvTable& csv, const QStringList& expected) {
        std::vector<int> indices;
        for (const QString& name : expected) indices.push_back(csv.requireColumn(name));
        for (std::size_t i = 0; i < csv.header().size(); ++i)
            if (!expected.contains(csv.header()[i]))
                throw BundleException({csv.fileName(), 1, int(i) + 1,
                                       QStringLiteral("unknown column '%1' (expected %2)")
                                           .arg(csv.header()[i], expected.join(QLatin1Char(',')))});
        return indices;
    }

    /// Temperatures logged in kelvin instead of °C are the classic mix-up: the
    /// median of a channel above 200 cannot be a °C reading on a machine tool.
    void checkTemperatureUnits() {
        for (std::size_t k = 0; k < m_campaign.sample_columns.size(); ++k) {
            const Channel* ch = m_campaign.findChannel(m_campaign.sample_columns[k]);
            if (!ch || ch->quantity != Quantity::Temperature) continue;
            std::vector<double> present;
            for (const Run& run : m_campaign.runs)
                for (double v : run.samples.values[k])
                    if (!std::isnan(v)) present.push_back(v);
            if (present.empty()) continue;
            auto mid = present.begin() + std::ptrdiff_t(present.size() / 2);
            std::nth_element(present.begin(), mid, present.end());
            if (*mid > 200.0)
                throw BundleException(
                    {kSamplesFile, 1, m_sampleHeaderColumns[k] + 1,
                     QStringLiteral("temperature channel '%1' reads %2 in the median: "
                                    "that looks like kelvin, DriftLab expects °C")
                         .arg(ch->id)
                         .arg(*mid)});
        }
    }

    QDir m_dir;
    const BundleReadOptions& m_options;
    Campaign m_campaign;
    QHash<QString, int> m_runIndex;
    std::vector<int> m_sampleHeaderColumns;  ///< samples.csv column of each sample_columns entry
    int m_emptyRows = 0;
    int m_firstEmptyRowLine = 0;
};

}  // namespace

BundleReadResult readBundle(const QString& directory, const BundleReadOptions& options) {
    BundleReadResult result;
    if (!QFileInfo(directory).isDir()) {
        result.error = BundleError{directory, 0, 0, QStringLiteral("not a bundle folder")};
        return result;
    }
    BundleParser parser(directory, options);
    try {
        result.campaign = parser.parse();
        result.warnings = parser.warnings;
    } catch (const BundleException& e) {
        result.error = e.error;
    }
    return result;
}

}  // namespace driftlab
