#pragma once
// The bundle reader's parser, shared by its two source files: BundleReader.cpp
// (campaign.json and samples.csv) and RunTablesReader.cpp (motion.csv and
// positioning.csv). Internal to core/bundle; the public entry is BundleReader.h.

#include <QHash>
#include <QString>
#include <QStringList>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "core/bundle/BundleReader.h"
#include "core/bundle/CsvTable.h"
#include "core/domain/Units.h"

namespace driftlab::bundle::files {
inline const QString kCampaign = QStringLiteral("campaign.json");
inline const QString kSamples = QStringLiteral("samples.csv");
inline const QString kMotion = QStringLiteral("motion.csv");
inline const QString kPositioning = QStringLiteral("positioning.csv");
}  // namespace driftlab::bundle::files

namespace driftlab::bundle {

/// Where a run's last record in motion.csv or positioning.csv stands (times
/// increase within a run, so it holds the run's latest time): that time is
/// checked on the run's clock once samples.csv has set that clock.
struct LastRecord {
    int line = 0;  ///< 0: the run has no record in the file
    int column = 0;
};

/// Positions past the travel: an axis overshoots its end targets to reverse
/// (ISO 230-2 overrun), so they are normal; counted for one warning per file.
struct Overrun {
    int count = 0;
    int firstLine = 0;
    double furthest_mm = 0;  ///< largest distance outside the travel
};

class BundleParser {
public:
    BundleParser(const BundleSource& source, const BundleReadOptions& options)
        : m_source(source), m_options(options) {}

    Campaign parse();

    QStringList warnings;

private:
    std::unique_ptr<CsvTable> openCsv(const QString& name);
    std::size_t runOf(const CsvTable& csv, int column);
    void setPositionLimits();
    void checkPosition(const CsvTable& csv, int column, double position_mm, Overrun& overrun);
    void warnOverrun(const QString& file, const Overrun& overrun);
    const Channel* sampleChannel(const CsvTable& csv, int column, UnitConversion* unit) const;
    static QString axisColumnOf(const QString& header);
    void check(const CsvTable& csv, int column, const std::optional<QString>& why);
    std::vector<int> formatColumns(const CsvTable& csv, const QStringList& expected);
    void reportProgress(const CsvTable& csv, double begin, double span);

    void readSamples();
    void moveOntoRunClocks(const std::vector<std::optional<double>>& offset_s);
    void warnNothingLogged(const std::vector<std::optional<double>>& firstRowSeen);
    void checkRunClockTimes(const std::vector<std::optional<double>>& offset_s) const;
    void readMotion();
    void readPositioning();
    void countCyclesFromZero();

    const BundleSource& m_source;
    const BundleReadOptions& m_options;
    Campaign m_campaign;
    QHash<QString, int> m_runIndex;
    std::vector<LastRecord> m_lastMotion, m_lastPositioning;  // per run
    double m_positionMin_mm = -std::numeric_limits<double>::infinity();
    double m_positionMax_mm = std::numeric_limits<double>::infinity();
};

}  // namespace driftlab::bundle
