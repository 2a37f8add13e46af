#pragma once
// The measurement uncertainty of the ISO 230-2 axis values: the contributors
// ISO 230-2 (annex A) and ISO/TR 230-9 name, each as a standard uncertainty in
// µm, combined per value by the root sum of squares and expanded by k
// (docs/acceptance.md has the equations and why each value takes which).

#include <QString>
#include <QStringList>
#include <vector>

#include "core/interferometer/AirRefractiveIndex.h"
#include "core/iso/AcceptanceSpecification.h"

namespace driftlab::iso {

/// The relative change of the air's refractive index, and so of the length an
/// interferometer reports, per unit of each environment reading at `air`:
/// central differences of the updated Edlén equation.
struct EdlenSensitivities {
    double per_K = 0;    ///< |∂n/∂t|, 1/K (≈ 0.93e-6 at 20 °C, 101325 Pa, 50 %RH)
    double per_hPa = 0;  ///< |∂n/∂p|, 1/hPa (≈ 0.27e-6)
    double per_pct = 0;  ///< |∂n/∂RH|, 1/%RH (≈ 0.0085e-6)
};
EdlenSensitivities edlenSensitivities(const interferometer::AirState& air);

/// Where the contributors are evaluated.
struct UncertaintyConditions {
    double length_mm = 0;                ///< measured length: the travel between the end targets
    double expansion_per_K = 11.5e-6;    ///< α of the machine's scale or screw
    double material_temperature_C = 20;  ///< mean during the test
    interferometer::AirState air;        ///< mean air during the test
    double eve_um = 0;                   ///< environmental variation error
    QString eve_source;                  ///< "eve_um of the specification", "ETVE run E1", …
};

struct UncertaintyContribution {
    QString key;       ///< "device", "environment", "material_temperature", …
    QString name;      ///< "measuring device (calibration)"
    QString equation;  ///< how it was computed, with the numbers
    double standard_um = 0;
    bool length_dependent = false;  ///< scales with the measured length
};

/// One axis value's combined and expanded uncertainty.
struct ParameterUncertainty {
    QString parameter;         ///< "A", "E", "R", "B", …
    QStringList contributors;  ///< the keys of the contributions it takes
    double combined_um = 0;    ///< u_c = √Σu²
    double expanded_um = 0;    ///< U = k·u_c
};

struct UncertaintyBudget {
    UncertaintyConditions conditions;
    double coverage_k = 2;
    std::vector<UncertaintyContribution> contributions;
    std::vector<ParameterUncertainty> parameters;  ///< in iso230_2ParameterKeys() order
    QStringList notes;                             ///< contributors set to 0 and what that assumes

    const ParameterUncertainty* find(const QString& parameter) const;
    const UncertaintyContribution* contribution(const QString& key) const;
};

/// The budget of `setup` under `conditions`.
UncertaintyBudget uncertaintyBudget(const SetupUncertainty& setup,
                                    const UncertaintyConditions& conditions);

}  // namespace driftlab::iso
