#pragma once
// A pitch-error compensation table for one axis: equally spaced points and,
// at each, the correction a controller adds to the commanded position
// (docs/compensation.md has the sign conventions and the formats).
//
// Sign convention: the laser reads deviation = actual − target (ISO 230-2);
// the correction is −deviation, so that commanded + correction lands the
// axis on the target. Every correction is in µm, every position in mm.

#include <QString>
#include <QStringList>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "core/compensation/TableOptions.h"
#include "core/iso/Iso230_2.h"

namespace driftlab::compensation {

/// How the table is laid out over the axis.
struct TableSettings {
    /// First and last point; default: the measured targets' span. A table
    /// never reaches beyond the measured span: no extrapolation (refused).
    std::optional<double> start_mm;
    std::optional<double> end_mm;
    /// At most one of spacing_mm (> 0) and points (≥ 2) is set; with neither,
    /// the table has as many points as there are measured targets. With a
    /// spacing that does not divide the range, the table ends at the last
    /// whole step before end_mm (a warning says so).
    double spacing_mm = 0;
    int points = 0;
    /// Separate + and − columns instead of their mean plus one backlash value.
    bool bidirectional = false;
    /// The most points any format takes (formats refuse fewer themselves).
    int max_points = 1024;
    /// How the values are written (--sign, --values); unset: the format's own
    /// convention. Carried to the table for the exporters.
    std::optional<ValueSign> sign;
    std::optional<ValueMode> values;
    /// The screw's lead (campaign screw.lead_mm); 0: unknown. Targets that all
    /// sit at one phase of the lead alias its periodic error (a warning).
    double screw_lead_mm = 0;

    bool isValid(QString* why) const;
};

/// Limits that protect the machine from a bad table. Infinity = no limit.
struct Limits {
    double max_value_um = 100;  ///< |correction| at any point
    double max_step_um = 20;    ///< |difference| between neighbouring points
    /// |difference| against the previous table at the same point, per update.
    double max_change_um = std::numeric_limits<double>::infinity();

    bool isValid(QString* why) const;
};

struct CompensationTable {
    std::vector<double> position_mm;  ///< strictly increasing, equally spaced
    /// Correction for the positive approach (↑, direction '+'), = −x̄↑ in a
    /// bidirectional table; the mean correction −x̄ in a unidirectional one.
    std::vector<double> correction_plus_um;
    /// Correction for the negative approach (↓); equals the + column in a
    /// unidirectional table.
    std::vector<double> correction_minus_um;
    bool bidirectional = false;
    /// B̄, the mean reversal x̄↑ − x̄↓ over the targets (ISO 230-2 sign; a
    /// screw with lost motion has B̄ < 0). NaN when one direction was not
    /// measured. A unidirectional table leaves it to the controller's
    /// backlash compensation.
    double mean_reversal_um = std::numeric_limits<double>::quiet_NaN();
    /// The expanded uncertainty (95 %, k = 2) of each point's correction: the
    /// mean deviations' (their cycles' scatter, s/√n, the larger of the two
    /// directions) and the added thermal error's prediction interval, in
    /// quadrature. Empty for a table built from a controller's read-back.
    std::vector<double> uncertainty_um;
    /// How an exporter writes the values; unset: the format's own convention.
    /// The columns above hold corrections whatever these say.
    std::optional<ValueSign> sign;
    std::optional<ValueMode> values;

    std::size_t size() const { return position_mm.size(); }
    double spacing_mm() const {
        return size() > 1 ? (position_mm.back() - position_mm.front()) / double(size() - 1) : 0;
    }
    /// The mean of both columns at point i: the unidirectional correction.
    double meanCorrectionUm(std::size_t i) const {
        return (correction_plus_um[i] + correction_minus_um[i]) / 2;
    }
    /// The largest |correction| over both columns.
    double maxAbsCorrectionUm() const;
    /// The + column (`plus`) or the − column as a file holds it: the mean of
    /// both in a unidirectional table, turned into `sign`, and with
    /// Incremental the change from the previous point (the first from 0).
    std::vector<double> writtenValuesUm(bool plus, ValueSign sign, ValueMode mode) const;
};

/// What buildTable() gives: the table, or why there is none.
struct TableResult {
    QString error;  ///< empty on success; names the point and value at fault
    CompensationTable table;
    QStringList warnings;
    bool ok() const { return error.isEmpty(); }
};

/// An extra error (µm, actual − target sign) at a position, e.g. a thermal
/// model's error at a stated state; it is added to the cold deviation.
using ErrorProfile = std::function<double(double position_mm)>;

/// The table from an ISO 230-2 evaluation's per-target mean deviations (the
/// cold geometric error of a laser calibration), plus `extra` when given,
/// whose 95 % half-width is `extraUncertainty` (µm at a position). Values
/// between targets are interpolated linearly.
TableResult buildTable(const iso::Evaluation& evaluation, const TableSettings& settings,
                       const Limits& limits = {}, const ErrorProfile& extra = {},
                       const ErrorProfile& extraUncertainty = {});

/// Empty when `table` is well formed (positions finite and strictly
/// increasing, values finite, column lengths equal, at most `max_points`
/// points) and within `limits`; otherwise the first fault, naming the point.
QString validate(const CompensationTable& table, const Limits& limits, int max_points);

/// Empty when every point of `next` differs from `previous` by at most
/// limits.max_change_um; the tables must have the same points.
QString checkChange(const CompensationTable& previous, const CompensationTable& next,
                    const Limits& limits);

}  // namespace driftlab::compensation
