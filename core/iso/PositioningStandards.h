#pragma once
// The same positioning readings evaluated by each standard whose definitions
// could be sourced: ISO 230-2 (2014, 2006, 1997), GB/T 17421.2-2016 and the
// JIS B 0182:1993 vocabulary, as a calibration lab's laser software shows them
// side by side. Standards a lab also names (VDI/DGQ 3441, ASME B5.54,
// JIS B 6192) are listed with the reason they are left out instead of being
// guessed. docs/standards.md gives every definition and where it comes from.

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/iso/Iso230_2.h"

namespace driftlab::iso {

enum class PositioningStandard {
    Iso230_2_2014,
    Iso230_2_2006,
    Iso230_2_1997,
    GbT17421_2_2016,
    JisB0182_1993,
};

/// The name on the command line: "iso230-2:2014", "gbt17421.2", "jis-b0182".
QString standardId(PositioningStandard standard);
/// The name as printed: "ISO 230-2:2014", "GB/T 17421.2-2016", "JIS B 0182:1993".
QString standardTitle(PositioningStandard standard);
/// The standard of an id (case-insensitive); nullopt for an unknown or a left-out one.
std::optional<PositioningStandard> standardFromId(const QString& id);
/// The ISO 230-2 edition a standard is, or nullopt for another standard.
std::optional<Edition> isoEditionOf(PositioningStandard standard);
/// Every evaluated standard, in the order of a comparison.
const std::vector<PositioningStandard>& positioningStandards();

/// A standard that is asked for but not evaluated, and why.
struct LeftOutStandard {
    QString id;     ///< the name it would have on the command line, "vdi3441"
    QString title;  ///< "VDI/DGQ 3441"
    QString why;    ///< what could not be sourced
};
const std::vector<LeftOutStandard>& leftOutStandards();
/// The left-out standard of an id (case-insensitive), or nullptr.
const LeftOutStandard* leftOutStandard(const QString& id);

/// One axis value as a standard defines it. NaN = not determined.
struct StandardValue {
    QString key;      ///< JSON key, as `iso230-2 --json` names it: "A", "R_up", "B_mean"
    QString symbol;   ///< as printed: "A", "R↑", "B̄"
    QString meaning;  ///< "bidirectional accuracy"
    double value_um = kNotDetermined;
};

/// The values of one standard, or why there are none.
struct StandardEvaluation {
    PositioningStandard standard = PositioningStandard::Iso230_2_2014;
    QString error;  ///< empty on success
    /// k as the standard fixes it (R↑_i = 2k·s↑_i and so on).
    double coverage_factor = 2;
    /// Approaches per direction at every target that the standard asks for;
    /// 0 where the standard states none.
    int min_approaches = 0;
    /// What the values are, in one line: the coverage and the formulas that differ.
    QString definitions;
    std::vector<StandardValue> values;  ///< in the order they are printed
    int targets = 0;
    int cycles = 0;
    QStringList skipped;   ///< values not determined and why
    QStringList warnings;  ///< as Evaluation::warnings, minimums of other standards left out

    bool ok() const { return error.isEmpty(); }
    /// The value with this JSON key, or nullptr when the standard does not define it.
    const StandardValue* value(const QString& key) const;
};

/// Evaluates `readings` by `standard`. The coverage factor and edition are the
/// standard's own; only `base`'s long-axis length and target tolerance are used.
StandardEvaluation evaluateStandard(const std::vector<Reading>& readings,
                                    PositioningStandard standard, const Settings& base = {});

/// Every evaluated standard on the same readings.
struct StandardsComparison {
    QString error;  ///< the first failure, naming the standard; empty on success
    std::vector<StandardEvaluation> evaluations;  ///< in positioningStandards() order
    QStringList warnings;                         ///< those of all standards, each once

    bool ok() const { return error.isEmpty(); }
};

StandardsComparison compareStandards(const std::vector<Reading>& readings,
                                     const Settings& base = {});

/// The rows of a comparison table: every key any standard defines, once, in
/// the order the standards list them (pointing into `comparison`).
std::vector<const StandardValue*> comparisonRows(const StandardsComparison& comparison);

}  // namespace driftlab::iso
