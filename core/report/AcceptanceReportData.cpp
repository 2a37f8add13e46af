#include "core/report/AcceptanceReportData.h"

#include <QJsonValue>

#include "core/iso/DriftAcceptance.h"
#include "core/iso/PositioningRuns.h"
#include "core/report/ReportAnalyses.h"

namespace driftlab::report {
namespace {

/// Keys under which lab tools put a date into campaign.json (kept in `extra`).
const QStringList kDateKeys{QStringLiteral("date"), QStringLiteral("started_at"),
                            QStringLiteral("start_date"), QStringLiteral("created_at")};

QString dateIn(const QJsonObject& extra) {
    for (const QString& key : kDateKeys)
        if (extra.value(key).isString()) return extra.value(key).toString();
    return {};
}

Cover cover(const Campaign& campaign, const ReportOptions& options) {
    Cover c;
    c.campaign = campaign.name;
    c.machine = campaign.machine.name;
    c.axis = campaign.machine.axis;
    c.controller = campaign.machine.controller;
    QStringList dates;
    if (const QString d = dateIn(campaign.extra); !d.isEmpty()) dates << d;
    for (const Run& run : campaign.runs) {
        c.runs.push_back({run.id, toString(run.kind), run.description});
        if (const QString d = dateIn(run.extra); !d.isEmpty())
            dates << QStringLiteral("%1: %2").arg(run.id, d);
    }
    c.campaign_dates = dates.isEmpty() ? QStringLiteral("not recorded in the campaign")
                                       : dates.join(QStringLiteral("; "));
    c.report_date = options.report_date;
    c.operator_name =
        options.operator_name.isEmpty() ? QStringLiteral("not given") : options.operator_name;
    c.version = options.version;
    return c;
}

/// The run `iso230-2` would take; when it would ask to choose, the first
/// run with readings, and the note says so.
QString positioningRun(const Campaign& campaign, const QString& wanted, QString* note,
                       QString* notApplicable) {
    if (!wanted.isEmpty()) {
        const Run* run = campaign.findRun(wanted);
        if (!run)
            *notApplicable = QStringLiteral("no run '%1' in the campaign").arg(wanted);
        else if (run->positioning.empty())
            *notApplicable = QStringLiteral("run %1 has no positioning readings").arg(wanted);
        return wanted;
    }
    const iso::DefaultRun chosen = iso::defaultPositioningRun(campaign);
    if (!chosen.id.isEmpty()) return chosen.id;
    if (chosen.choices.isEmpty()) {
        *notApplicable = QStringLiteral("no run with positioning readings");
        return {};
    }
    *note = QStringLiteral("run %1 evaluated, the first of %2 (--run chooses another)")
                .arg(chosen.choices.front(), chosen.choices.join(QStringLiteral(", ")));
    return chosen.choices.front();
}

/// The specification the report applies: the caller's, else the campaign's own.
struct AppliedSpecification {
    std::optional<iso::AcceptanceSpecification> spec;
    QString error;  ///< why the campaign's own could not be read
};

AppliedSpecification appliedSpecification(const Campaign& campaign, const ReportOptions& options) {
    AppliedSpecification applied;
    applied.spec =
        options.acceptance ? options.acceptance : iso::campaignAcceptance(campaign, &applied.error);
    return applied;
}

PositioningSection positioning(const Campaign& campaign, const ReportOptions& options,
                               const AppliedSpecification& applied) {
    PositioningSection s;
    s.run_id = positioningRun(campaign, options.positioning_run, &s.run_note, &s.not_applicable);
    if (!s.not_applicable.isEmpty()) return s;
    const Run& run = *campaign.findRun(s.run_id);
    std::vector<iso::Reading> readings = iso::readingsOf(run);
    s.evaluation = iso::evaluate(readings, options.iso_settings);
    QString error = applied.error;
    const auto& spec = applied.spec;
    if (spec && s.evaluation.ok()) {
        iso::PositioningAcceptance acceptance =
            iso::evaluateAcceptance(campaign, run, *spec, options.iso_settings);
        if (acceptance.ok()) {
            // Every standard then compares the same readings at 20 °C.
            s.evaluation = acceptance.evaluation;
            readings = acceptance.readings;
            s.acceptance = std::move(acceptance);
        } else {
            error = acceptance.error;
        }
    }
    s.acceptance_error = error;
    if (!s.evaluation.ok())
        s.not_applicable = QStringLiteral("run %1: %2").arg(s.run_id, s.evaluation.error);
    else
        s.standards = iso::compareStandards(readings, options.iso_settings);
    return s;
}

DriftSection drift(const Campaign& campaign, const ReportOptions& options,
                   const AppliedSpecification& applied) {
    DriftSection s;
    const auto& spec = applied.spec;
    const auto decide = [&](const QString& run, const iso::DriftFigures& figures) {
        if (spec)
            if (auto d = iso::driftDecisions(*spec, campaign.machine.axis, figures); !d.empty())
                s.decisions[run] = std::move(d);
    };
    for (const Run& run : campaign.runs) {
        if (run.kind == RunKind::Moving && !run.positioning.empty()) {
            iso::AxisDriftEvaluation e = iso::evaluateAxisDrift(run, options.drift_settings);
            if (e.ok()) {
                decide(run.id, iso::driftFigures(e));
                s.axis_runs.push_back(std::move(e));
            } else {
                s.errors << e.error;
            }
        } else if (run.kind == RunKind::Spindle || run.kind == RunKind::Etve) {
            iso::ProbeDriftEvaluation e =
                iso::evaluateProbeDrift(campaign, run, options.drift_settings);
            if (e.ok()) {
                decide(run.id, iso::driftFigures(e));
                s.probe_runs.push_back(std::move(e));
            } else {
                s.errors << e.error;
            }
        }
    }
    if (s.axis_runs.empty())
        s.axis_not_applicable = QStringLiteral("no moving run with positioning readings");
    if (s.probe_runs.empty()) s.probe_not_applicable = QStringLiteral("no spindle or ETVE run");
    if (s.axis_runs.empty() && s.probe_runs.empty() && s.errors.isEmpty())
        s.not_applicable = QStringLiteral("no moving, spindle or ETVE run");
    return s;
}

}  // namespace

AcceptanceReportData buildReportData(const Campaign& campaign, const ReportOptions& options) {
    AcceptanceReportData data;
    // The cross-state matrix and the diagnosis take nearly all the time:
    // they share the progress bar; the ISO evaluations are instant.
    const auto part = [&](double from, double to) {
        return [&options, &data, from, to](double f) {
            if (options.progress && !options.progress(from + (to - from) * f))
                data.cancelled = true;
            return !data.cancelled;
        };
    };
    data.cover = cover(campaign, options);
    // Read once: both ISO sections decide against the same specification.
    const AppliedSpecification applied = appliedSpecification(campaign, options);
    data.positioning = positioning(campaign, options, applied);
    data.drift = drift(campaign, options, applied);
    if (!part(0, 0.02)(1)) return data;
    data.models = compareModels(campaign, part(0.02, 0.6));
    if (data.cancelled) return data;
    data.diagnosis = diagnoseCampaign(campaign, part(0.6, 0.98));
    if (data.cancelled) return data;
    data.compensation = compensate(data.positioning);
    part(0.98, 1)(1);
    return data;
}

double correctionAt(const compensation::CompensationTable& table, double position_mm,
                    Direction direction) {
    const std::vector<double>& c =
        direction == Direction::Positive ? table.correction_plus_um : table.correction_minus_um;
    const std::vector<double>& x = table.position_mm;
    if (x.empty()) return iso::kNotDetermined;
    if (position_mm <= x.front()) return c.front();
    if (position_mm >= x.back()) return c.back();
    std::size_t i = 1;
    while (x[i] < position_mm) ++i;
    const double w = (position_mm - x[i - 1]) / (x[i] - x[i - 1]);
    return c[i - 1] + w * (c[i] - c[i - 1]);
}

}  // namespace driftlab::report
