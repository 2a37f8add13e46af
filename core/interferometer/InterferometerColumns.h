#pragma once
// Which column of an interferometer software's CSV export holds which
// quantity of DriftLab's generic layout (docs/interferometer.md). Vendor
// packages name their columns their own way ("Error [µm]", "Pos."): the user
// maps them once, and the reader then applies every check of the layout.

#include <QString>
#include <array>
#include <optional>
#include <vector>

namespace driftlab::interferometer {

/// The quantities a reading row carries, in the layout's column order.
enum class ReadingRole { Time, Position, Deviation, Air, Pressure, Humidity, Material };
inline constexpr std::array kReadingRoles = {
    ReadingRole::Time,     ReadingRole::Position, ReadingRole::Deviation, ReadingRole::Air,
    ReadingRole::Pressure, ReadingRole::Humidity, ReadingRole::Material};

/// The layout's column name of a role ("time_s").
QString layoutColumn(ReadingRole role);
/// What a user reads for the role ("air temperature [°C]").
QString roleLabel(ReadingRole role);
/// Time, position and deviation: a reading has no meaning without them.
bool isRequired(ReadingRole role);

struct ColumnMapping {
    /// Per role: nullopt finds the layout's own column (also capitalised and
    /// with its unit, core/bundle/ColumnSpelling.h); an empty string reads
    /// none (an optional role only); otherwise the file's header, exactly.
    std::array<std::optional<QString>, kReadingRoles.size()> columns;

    std::optional<QString>& operator[](ReadingRole role) { return columns[std::size_t(role)]; }
    const std::optional<QString>& operator[](ReadingRole role) const {
        return columns[std::size_t(role)];
    }
};

/// The header column a role most likely is, for preselection: the layout's
/// spelling first, then the words vendors use ("Error" for the deviation,
/// "Pos" for the position); nullopt when none fits.
std::optional<int> guessColumn(ReadingRole role, const std::vector<QString>& header);

}  // namespace driftlab::interferometer
