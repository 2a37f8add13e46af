#pragma once
// What an acceptance report says about a campaign, gathered once and rendered
// as PDF, HTML or CSV by ui/report (docs/report.md). Plain values only: the
// renderers format, they never compute. A section that does not apply to the
// campaign carries a one-line `not_applicable` instead of failing the report.

#include <QString>
#include <QStringList>
#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/compensation/CompensationTable.h"
#include "core/diagnosis/Diagnosis.h"
#include "core/domain/Campaign.h"
#include "core/history/MachineHistory.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/Iso230_3.h"
#include "core/iso/PositioningAcceptance.h"
#include "core/iso/PositioningStandards.h"
#include "core/models/ModelScore.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::report {

struct ReportOptions {
    /// The ISO 230-2 and compensation run; empty: as `iso230-2` chooses it
    /// (the positioning run, else the only run with readings), else the first
    /// run with readings (said so in the report).
    QString positioning_run;
    QString operator_name;  ///< empty: "not given"
    QString version;        ///< DRIFTLAB_VERSION of the caller
    QString report_date;    ///< ISO 8601, set by the caller (tests pin it)
    iso::Settings iso_settings;
    iso::DriftSettings drift_settings;
    /// Tolerances, set-up uncertainty and 20 °C; none: the campaign's own
    /// `acceptance` object, if it has one.
    std::optional<iso::AcceptanceSpecification> acceptance;
    /// The fraction done; returning false cancels (the cross-state matrix and
    /// the diagnosis are the expensive parts and check it often).
    std::function<bool(double fraction)> progress;
};

struct RunLine {
    QString id, kind, description;
};

struct Cover {
    QString campaign, machine, axis, controller;
    std::vector<RunLine> runs;
    QString campaign_dates;  ///< from the campaign's or runs' own date keys; "not recorded"
    QString report_date, operator_name, version;
};

struct PositioningSection {
    QString not_applicable;
    QString run_id;
    QString run_note;            ///< how the run was chosen when it was not given
    iso::Evaluation evaluation;  ///< at 20 °C when `acceptance` normalised it
    /// With a specification: environment, budget and verdicts.
    std::optional<iso::PositioningAcceptance> acceptance;
    QString acceptance_error;  ///< why a specification could not be applied
    /// The same readings by every positioning standard (docs/standards.md).
    iso::StandardsComparison standards;
};

struct DriftSection {
    QString not_applicable;        ///< no moving, spindle or ETVE run at all
    QString probe_not_applicable;  ///< "no spindle or ETVE run" when only moving runs
    QString axis_not_applicable;   ///< "no moving run with positioning readings"
    std::vector<iso::AxisDriftEvaluation> axis_runs;
    std::vector<iso::ProbeDriftEvaluation> probe_runs;
    QStringList errors;  ///< runs that could not be evaluated, and why
    /// By run id: the drift figures against the specification's tolerances.
    std::map<QString, std::vector<iso::Decision>> decisions;
};

struct ModelMatrix {
    QString model;
    models::CrossStateMatrix matrix;
};

struct ModelSection {
    QString not_applicable;
    QStringList runs;
    std::vector<ModelMatrix> models;
    QString diagonal;                   ///< what the diagonal is
    std::vector<models::DataGap> gaps;  ///< holes in the log of the runs compared
};

struct DiagnosisSection {
    QString not_applicable;
    diagnosis::DiagnosisResult result;
    std::vector<models::RunData> test_runs;  ///< the held-out runs, for the plots
};

/// Positioning error at one target before and after the table: after =
/// measured mean deviation + the table's correction interpolated there.
struct CompensatedTarget {
    double target_mm = 0;
    double before_up_um = iso::kNotDetermined, before_down_um = iso::kNotDetermined;
    double after_up_um = iso::kNotDetermined, after_down_um = iso::kNotDetermined;
};

struct CompensationSection {
    QString not_applicable;
    QString run_id;
    compensation::CompensationTable table;
    QStringList warnings;
    std::vector<CompensatedTarget> targets;
    double before_peak_um = 0;    ///< largest |x̄↑|, |x̄↓| over the targets
    double residual_peak_um = 0;  ///< largest |after| over the targets
};

/// Every campaign of the report's machine and axis in its store (docs/history.md),
/// set by a caller that has the store: a bundle has no history.
struct HistorySection {
    std::optional<history::MachineHistory> history;
    qint64 campaign_id = 0;  ///< the report's campaign in the store
    /// The section is printed only where there is a trend to see.
    bool shown() const { return history && history->entries.size() > 1; }
};

struct AcceptanceReportData {
    QString error;  ///< empty on success (and when cancelled)
    bool cancelled = false;
    Cover cover;
    PositioningSection positioning;
    DriftSection drift;
    ModelSection models;
    DiagnosisSection diagnosis;
    CompensationSection compensation;
    HistorySection history;
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// Gathers every section of the report of `campaign`. Never throws; a
/// section that does not apply says so, a cancel sets `cancelled`.
AcceptanceReportData buildReportData(const Campaign& campaign, const ReportOptions& options);

/// The table's correction at a position for one approach, linear between
/// points, the end value beyond them.
double correctionAt(const compensation::CompensationTable& table, double position_mm,
                    Direction direction);

}  // namespace driftlab::report
