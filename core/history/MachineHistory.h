#pragma once
// The history of one machine axis over its test campaigns (docs/history.md):
// each campaign's ISO 230-2 figures (A, E, R, B, M) and ISO 230-3 drift,
// in the order of the campaigns' dates, with the change of each figure from
// the previous and from the first campaign. Plain data; db/MachineHistoryStore
// gathers the campaigns of a store, the CLI, the report and the GUI show it.

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::history {

/// Keys under which campaign.json (top level or a run's object) records when
/// a campaign or a run took place; the report's cover reads the same keys.
QStringList dateKeys();

/// When a campaign took place and where that was read.
struct CampaignDate {
    QDateTime utc;
    /// "campaign.json date", "run S1 started_at", "import time"
    QString source;
};

/// The earliest date campaign.json records for the campaign or any of its
/// runs (ISO 8601; a date alone is midnight UTC, a time without zone is UTC);
/// nullopt when it records none that can be read.
std::optional<CampaignDate> recordedDate(const Campaign& campaign);

/// The ISO 230-2 axis figures the history follows.
enum class Figure { A, E, R, B, M };
inline constexpr Figure kFigures[] = {Figure::A, Figure::E, Figure::R, Figure::B, Figure::M};
/// "A", "E", ...: the keys of the JSON and the columns of the table.
QString figureName(Figure figure);
/// "bidirectional accuracy", ...
QString figureMeaning(Figure figure);

/// ISO 230-2 of one campaign on its positioning run (iso::choosePositioningRun).
struct PositioningFigures {
    QString run_id;          ///< empty when not evaluated
    QString run_note;        ///< how the run was chosen when the campaign left a choice
    QString not_determined;  ///< why there are no figures; empty when there are
    iso::Evaluation evaluation;
    /// NaN where the evaluation gives none (or there is none).
    double value_um(Figure figure) const;
};

/// ISO 230-3 drift of one campaign: its first moving run with positioning readings.
struct DriftFigures {
    QString run_id;                             ///< empty when there is no such run
    QString not_determined;                     ///< why there are no figures; empty when there are
    double max_drift_um = iso::kNotDetermined;  ///< the largest |drift|, with its sign
    double range_um = iso::kNotDetermined;      ///< the largest range of a target's drift
    double stabilised_time_s = iso::kNotStabilised;  ///< NaN: not stabilised within the run
    bool determined() const { return not_determined.isEmpty() && !run_id.isEmpty(); }
};

struct HistoryEntry {
    qint64 campaign_id = 0;
    QString campaign;
    CampaignDate date;
    PositioningFigures positioning;
    DriftFigures drift;
};

struct HistorySettings {
    iso::Settings iso;
    iso::DriftSettings drift;
};

/// The figures of one campaign, dated `date`.
HistoryEntry historyEntry(const Campaign& campaign, qint64 campaignId, const CampaignDate& date,
                          const HistorySettings& settings = {});

struct MachineHistory {
    QString machine;
    QString axis;
    HistorySettings settings;
    std::vector<HistoryEntry> entries;  ///< by date, then by campaign id

    /// Figure of entry `i` less that of entry i − 1 (NaN for the first, or
    /// where either is not determined).
    double changeFromPrevious_um(std::size_t i, Figure figure) const;
    /// Figure of entry `i` less that of the first entry.
    double changeFromFirst_um(std::size_t i, Figure figure) const;
    /// The entry of a campaign, or nullptr.
    const HistoryEntry* find(qint64 campaignId) const;
};

/// Puts `entries` in time order: by date, campaigns of one date by id.
void orderByDate(std::vector<HistoryEntry>& entries);

}  // namespace driftlab::history
