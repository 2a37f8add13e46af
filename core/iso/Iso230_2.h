#pragma once
// ISO 230-2 evaluation of the accuracy and repeatability of positioning of a
// numerically controlled axis from repeated interferometer readings
// (docs/iso230.md has the definitions, the editions and the sources).
//
// Sign convention: deviation_um = actual position − target position (the
// standard's x_ij = P_ij − P_i). "↑" is the positive approach (direction '+'),
// "↓" the negative one. Every value is in µm except target_mm.

#include <QString>
#include <QStringList>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/domain/Run.h"

namespace driftlab::iso {

enum class Edition { Iso2014, Iso2006, Iso1997 };

/// "2014" → Edition::Iso2014, ...; nullopt for an edition not implemented.
std::optional<Edition> editionFromString(const QString& text);
/// "ISO 230-2:2014".
QString toString(Edition edition);
/// The year alone, 2014, for scripts.
int editionYear(Edition edition);

/// One reading of the interferometer at a target, approached in one direction.
struct Reading {
    double target_mm = 0;
    Direction direction = Direction::Positive;
    int cycle = 0;
    double deviation_um = 0;  ///< actual − target (ISO 230-2 sign)
};

/// The readings of a bundle's run (positioning.csv rows), in file order.
std::vector<Reading> readingsOf(const Run& run);

struct Settings {
    Edition edition = Edition::Iso2014;
    /// k of the expanded quantities: R↑_i = 2k·s↑_i, A with x̄ ± k·s. The
    /// standard's value is 2 (R↑_i = 4s↑_i).
    double coverage_factor = 2;
    /// Above this travel the standard allows one approach per direction per
    /// target; the s-based values are then skipped instead of refused.
    double long_axis_mm = 2000;
    /// Targets closer than this are the same target (readings logged as
    /// 100 and 100.0000001 by a tool that adds a float offset).
    double target_tolerance_mm = 1e-6;

    /// True when the settings can be used; otherwise `why` says what is wrong.
    bool isValid(QString* why) const;
};

/// Targets beyond ±100 m are no machine's (a unit or exponent slip).
constexpr double kMaxTarget_mm = 100000;

constexpr double kNotDetermined = std::numeric_limits<double>::quiet_NaN();

/// What is known at one target i. NaN = not determined (a skipped value).
struct TargetResult {
    double target_mm = 0;
    int n_up = 0;
    int n_down = 0;
    double mean_up_um = kNotDetermined;    ///< x̄↑_i: mean over the cycles at this target
    double mean_down_um = kNotDetermined;  ///< x̄↓_i
    double mean_um = kNotDetermined;       ///< x̄_i = (x̄↑_i + x̄↓_i) / 2
    double s_up_um = kNotDetermined;       ///< s↑_i, sample standard deviation (n − 1)
    double s_down_um = kNotDetermined;     ///< s↓_i
    double reversal_um = kNotDetermined;   ///< B_i = x̄↑_i − x̄↓_i
    double r_up_um = kNotDetermined;       ///< R↑_i = 2k·s↑_i
    double r_down_um = kNotDetermined;     ///< R↓_i = 2k·s↓_i
    double r_um = kNotDetermined;          ///< R_i = max(k·s↑ + k·s↓ + |B_i|, R↑_i, R↓_i)
};

/// The axis values. NaN = not determined (see Evaluation::skipped).
struct AxisResult {
    double reversal_um = kNotDetermined;       ///< B = max |B_i| (a magnitude)
    double mean_reversal_um = kNotDetermined;  ///< B̄: mean of the B_i
    double r_up_um = kNotDetermined;           ///< R↑ = max R↑_i
    double r_down_um = kNotDetermined;         ///< R↓ = max R↓_i
    double r_um = kNotDetermined;              ///< R = max R_i
    double e_up_um = kNotDetermined;           ///< E↑ = max x̄↑_i − min x̄↑_i
    double e_down_um = kNotDetermined;         ///< E↓ = max x̄↓_i − min x̄↓_i
    double e_um = kNotDetermined;              ///< E: over x̄↑_i and x̄↓_i together
    double m_um = kNotDetermined;              ///< M = max x̄_i − min x̄_i
    double a_up_um = kNotDetermined;  ///< A↑ = max(x̄↑ + k·s↑) − min(x̄↑ − k·s↑)
    double a_down_um = kNotDetermined;  ///< A↓
    double a_um = kNotDetermined;       ///< A: over both directions together
};

/// One axis value as every output names it, in the order ISO 230-2 lists them.
struct AxisValue {
    const char* key;      ///< JSON key of `iso230-2 --json`: "A", "R_up", "B_mean"
    const char* symbol;   ///< as printed: "A", "R↑", "B̄"
    const char* meaning;  ///< "bidirectional accuracy"
    double AxisResult::*value;
};
/// B, B̄, R↑, R↓, R, E↑, E↓, E, M, A↑, A↓, A.
const std::vector<AxisValue>& axisValues();
/// The value of `key` in `axis`; NaN for an unknown key.
double axisValue(const AxisResult& axis, const QString& key);

/// The result of evaluate(): the values, or why there are none.
struct Evaluation {
    QString error;  ///< empty on success
    Settings settings;
    std::vector<TargetResult> targets;  ///< ascending target_mm
    AxisResult axis;
    int cycles = 0;  ///< distinct cycle numbers among the readings
    /// Values not determined and why ("s, R, A: one approach per direction ...").
    QStringList skipped;
    /// What is unusual but not wrong: drift from cycle to cycle, repeated readings.
    QStringList warnings;

    bool ok() const { return error.isEmpty(); }
};

/// Evaluates `readings` under `settings`. Never throws: a failure is
/// Evaluation::error, naming the target and direction at fault.
Evaluation evaluate(const std::vector<Reading>& readings, const Settings& settings = {});

}  // namespace driftlab::iso
