#include "core/history/MachineHistory.h"

#include <QJsonObject>
#include <QJsonValue>
#include <algorithm>
#include <cmath>

#include "core/iso/PositioningAcceptance.h"
#include "core/iso/PositioningRuns.h"

namespace driftlab::history {
namespace {

/// An ISO 8601 date or date and time as lab tools write it ("2026-03-02",
/// "2026-03-02T08:15:00Z", "2026-03-02 08:15:00"); invalid when it is none.
/// A time without a zone is UTC, as the bundle reader reads a logger's clock.
QDateTime parseDate(const QString& text) {
    const QString t = text.trimmed();
    if (t.size() == 10) {
        const QDate day = QDate::fromString(t, Qt::ISODate);
        return day.isValid() ? QDateTime(day, QTime(0, 0), Qt::UTC) : QDateTime();
    }
    QString iso = t;
    if (iso.size() > 10 && iso[10] == QLatin1Char(' ')) iso[10] = QLatin1Char('T');
    const QDateTime read = QDateTime::fromString(iso, Qt::ISODateWithMs);
    if (!read.isValid()) return {};
    if (read.timeSpec() == Qt::LocalTime) return QDateTime(read.date(), read.time(), Qt::UTC);
    return read.toUTC();
}

/// The earliest readable date under the date keys of `object`, with its key.
std::optional<std::pair<QDateTime, QString>> earliestIn(const QJsonObject& object) {
    std::optional<std::pair<QDateTime, QString>> earliest;
    for (const QString& key : dateKeys()) {
        if (!object.value(key).isString()) continue;
        const QDateTime at = parseDate(object.value(key).toString());
        if (at.isValid() && (!earliest || at < earliest->first)) earliest.emplace(at, key);
    }
    return earliest;
}

PositioningFigures positioningFigures(const Campaign& campaign, const iso::Settings& settings) {
    PositioningFigures f;
    iso::PositioningRunChoice choice = iso::choosePositioningRun(campaign, {});
    if (!choice.run) {
        // Several runs with readings and none of kind positioning: the first,
        // as the report takes it, and said so.
        const iso::DefaultRun fallback = iso::defaultPositioningRun(campaign);
        if (fallback.choices.isEmpty()) {
            f.not_determined = choice.error;
            return f;
        }
        choice.run = campaign.findRun(fallback.choices.front());
        f.run_note =
            QStringLiteral("run %1 evaluated, the first of %2")
                .arg(fallback.choices.front(), fallback.choices.join(QStringLiteral(", ")));
    }
    f.run_id = choice.run->id;
    f.evaluation = iso::evaluate(iso::readingsOf(*choice.run), settings);
    // A campaign that carries its specification is evaluated as iso230-2
    // evaluates it: at 20 °C when the specification says so.
    QString error;
    if (const auto spec = iso::campaignAcceptance(campaign, &error); spec && f.evaluation.ok()) {
        const iso::PositioningAcceptance acceptance =
            iso::evaluateAcceptance(campaign, *choice.run, *spec, settings);
        if (acceptance.ok())
            f.evaluation = acceptance.evaluation;
        else
            error = acceptance.error;
    }
    if (!error.isEmpty())
        f.run_note += (f.run_note.isEmpty() ? QString() : QStringLiteral("; ")) +
                      QStringLiteral("its acceptance specification not applied: ") + error;
    if (!f.evaluation.ok())
        f.not_determined = QStringLiteral("run %1: %2").arg(f.run_id, f.evaluation.error);
    return f;
}

DriftFigures driftFigures(const Campaign& campaign, const iso::DriftSettings& settings) {
    DriftFigures f;
    const auto moving = std::find_if(campaign.runs.begin(), campaign.runs.end(), [](const Run& r) {
        return r.kind == RunKind::Moving && !r.positioning.empty();
    });
    if (moving == campaign.runs.end()) {
        f.not_determined = QStringLiteral("no moving run with positioning readings");
        return f;
    }
    f.run_id = moving->id;
    const iso::AxisDriftEvaluation e = iso::evaluateAxisDrift(*moving, settings);
    if (!e.ok()) {
        f.not_determined = e.error;
        return f;
    }
    f.max_drift_um = e.max_drift_um;
    f.range_um = 0;
    for (const iso::TargetDrift& t : e.targets) f.range_um = std::max(f.range_um, t.drift.range_um);
    f.stabilised_time_s = e.stabilised_time_s;
    return f;
}

}  // namespace

QStringList dateKeys() {
    return {QStringLiteral("date"), QStringLiteral("started_at"), QStringLiteral("start_date"),
            QStringLiteral("created_at")};
}

std::optional<CampaignDate> recordedDate(const Campaign& campaign) {
    std::optional<CampaignDate> date;
    if (const auto at = earliestIn(campaign.extra))
        date = CampaignDate{at->first, QStringLiteral("campaign.json %1").arg(at->second)};
    for (const Run& run : campaign.runs)
        if (const auto at = earliestIn(run.extra); at && (!date || at->first < date->utc))
            date = CampaignDate{at->first, QStringLiteral("run %1 %2").arg(run.id, at->second)};
    return date;
}

QString figureName(Figure figure) {
    switch (figure) {
        case Figure::A:
            return QStringLiteral("A");
        case Figure::E:
            return QStringLiteral("E");
        case Figure::R:
            return QStringLiteral("R");
        case Figure::B:
            return QStringLiteral("B");
        case Figure::M:
            return QStringLiteral("M");
    }
    return {};
}

QString figureMeaning(Figure figure) {
    switch (figure) {
        case Figure::A:
            return QStringLiteral("bidirectional accuracy");
        case Figure::E:
            return QStringLiteral("bidirectional systematic error");
        case Figure::R:
            return QStringLiteral("bidirectional repeatability");
        case Figure::B:
            return QStringLiteral("reversal error");
        case Figure::M:
            return QStringLiteral("mean bidirectional positioning error");
    }
    return {};
}

double PositioningFigures::value_um(Figure figure) const {
    if (!not_determined.isEmpty() || run_id.isEmpty()) return iso::kNotDetermined;
    const iso::AxisResult& a = evaluation.axis;
    switch (figure) {
        case Figure::A:
            return a.a_um;
        case Figure::E:
            return a.e_um;
        case Figure::R:
            return a.r_um;
        case Figure::B:
            return a.reversal_um;
        case Figure::M:
            return a.m_um;
    }
    return iso::kNotDetermined;
}

HistoryEntry historyEntry(const Campaign& campaign, qint64 campaignId, const CampaignDate& date,
                          const HistorySettings& settings) {
    HistoryEntry e;
    e.campaign_id = campaignId;
    e.campaign = campaign.name;
    e.date = date;
    e.positioning = positioningFigures(campaign, settings.iso);
    e.drift = driftFigures(campaign, settings.drift);
    return e;
}

double MachineHistory::changeFromPrevious_um(std::size_t i, Figure figure) const {
    if (i == 0 || i >= entries.size()) return iso::kNotDetermined;
    return entries[i].positioning.value_um(figure) - entries[i - 1].positioning.value_um(figure);
}

double MachineHistory::changeFromFirst_um(std::size_t i, Figure figure) const {
    if (i >= entries.size()) return iso::kNotDetermined;
    return entries[i].positioning.value_um(figure) - entries.front().positioning.value_um(figure);
}

const HistoryEntry* MachineHistory::find(qint64 campaignId) const {
    for (const HistoryEntry& e : entries)
        if (e.campaign_id == campaignId) return &e;
    return nullptr;
}

void orderByDate(std::vector<HistoryEntry>& entries) {
    std::sort(entries.begin(), entries.end(), [](const HistoryEntry& a, const HistoryEntry& b) {
        if (a.date.utc != b.date.utc) return a.date.utc < b.date.utc;
        return a.campaign_id < b.campaign_id;
    });
}

}  // namespace driftlab::history
