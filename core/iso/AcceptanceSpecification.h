#pragma once
// What a lab declares before it accepts an axis: the machine's tolerances, the
// uncertainty of its measuring set-up, and how the readings reach 20 °C
// (docs/acceptance.md). Read from a specification file
// (`driftlab.acceptance/1`) or from the `acceptance` object of campaign.json,
// so a campaign can carry the specification it was tested against.

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <map>
#include <optional>

#include "core/domain/Campaign.h"

namespace driftlab::iso {

inline const QString kAcceptanceFormat = QStringLiteral("driftlab.acceptance/1");

/// The ISO 230-2 axis values a tolerance can be set for, by their JSON keys.
const QStringList& iso230_2ParameterKeys();  // A, A_up, A_down, E, …, B, M
/// The ISO 230-3 axis figures a tolerance can be set for.
const QStringList& iso230_3ParameterKeys();  // max_drift, drift_range

/// The measuring set-up's uncertainties, each as its source states it. Sensor
/// accuracies are half-widths (±a) of a rectangular distribution, so their
/// standard uncertainty is a/√3; the interferometer's calibration is an
/// expanded uncertainty U = U0 + U_L·L at coverage factor k.
struct SetupUncertainty {
    double device_um = 0;               ///< U0 of the interferometer's calibration
    double device_ppm = 0;              ///< U_L, in µm per metre of measured length
    double device_k = 2;                ///< coverage factor of the calibration certificate
    double air_temperature_K = 0;       ///< ± accuracy of the air temperature sensor
    double air_pressure_hPa = 0;        ///< ± accuracy of the pressure sensor
    double air_humidity_pct = 0;        ///< ± accuracy of the humidity sensor, %RH
    double material_temperature_K = 0;  ///< ± accuracy of the material thermometers
    double expansion_per_K = 0;         ///< ± uncertainty of the expansion coefficient α
    double misalignment_mm = 0;         ///< beam-to-axis lateral offset over the travel
    std::optional<double> eve_um;       ///< environmental variation error, if measured apart
    QString eve_run;                    ///< or the ETVE run (machine at rest) that measures it
    double coverage_k = 2;              ///< k of the expanded uncertainty of each result
    bool operator==(const SetupUncertainty&) const = default;
};

/// How deviations are brought to 20 °C (ISO 1, the reference temperature).
struct TemperatureSetting {
    /// The machine's own scale or temperature compensation already refers its
    /// positions to 20 °C: DriftLab names it and corrects nothing.
    bool machine_compensates = false;
    /// Correct the readings by α·(θ − 20 °C)·P (nominal differential expansion).
    bool normalise = true;
    std::optional<double> expansion_per_K;  ///< α; default: the screw's alpha_per_K
    QStringList material_channels;          ///< 1…3 thermometers; default: role `structure`
    std::optional<double> material_temperature_C;  ///< when no thermometer was logged
    bool operator==(const TemperatureSetting&) const = default;
};

/// Upper tolerances, in µm, per axis name ("X").
struct AxisTolerances {
    std::map<QString, double> iso230_2_um;  ///< "A" → 12, …
    std::map<QString, double> iso230_3_um;  ///< "max_drift" → 20, …
    bool operator==(const AxisTolerances&) const = default;
};

struct AcceptanceSpecification {
    std::map<QString, AxisTolerances> axes;
    SetupUncertainty uncertainty;
    TemperatureSetting temperature;

    /// The tolerances of `axis`, or nullptr when the specification has none.
    const AxisTolerances* tolerancesOf(const QString& axis) const;
    bool operator==(const AcceptanceSpecification&) const = default;
};

/// Parses a specification object. Unknown keys, values of the wrong type or
/// sign, and a `format` other than driftlab.acceptance/1 are errors naming the
/// key path under `where` (the file name, or "campaign.json acceptance"): a
/// misspelt tolerance silently ignored would pass an axis it should not.
std::optional<AcceptanceSpecification> parseAcceptanceSpecification(const QJsonObject& object,
                                                                    const QString& where,
                                                                    QString* error);

/// Reads a specification file, also refusing a key named twice.
std::optional<AcceptanceSpecification> readAcceptanceSpecification(const QString& path,
                                                                   QString* error);

/// The campaign's own specification (the `acceptance` object of campaign.json);
/// nullopt without `error` when it has none, with `error` when it is malformed.
std::optional<AcceptanceSpecification> campaignAcceptance(const Campaign& campaign, QString* error);

/// The specification as JSON, in the form parseAcceptanceSpecification reads.
QJsonObject toJson(const AcceptanceSpecification& specification);

}  // namespace driftlab::iso
