#pragma once
// ISO 230-2 readings refer to 20 °C (ISO 1). A machine measured warm carries
// the expansion of its scale or screw in every deviation, α·(θ − 20 °C)·P,
// growing with the position P: the nominal differential expansion against
// the 20 °C length. This file summarises the test's air and material
// temperatures, as the standard asks a report to state them, and takes that
// expansion out of the readings (docs/acceptance.md).

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/Iso230_2.h"

namespace driftlab::iso {

/// One temperature over the test: the mean of its channels at each sample time.
struct TemperatureSummary {
    QStringList channels;
    double start_C = 0;
    double end_C = 0;
    double min_C = 0;
    double max_C = 0;
    double mean_C = 0;
    int samples = 0;
};

struct TestEnvironment {
    double start_s = 0;                          ///< first positioning reading
    double end_s = 0;                            ///< last positioning reading
    std::optional<TemperatureSummary> air;       ///< role `air`, else `ambient`
    std::optional<TemperatureSummary> material;  ///< the material thermometers
    QStringList notes;                           ///< what is missing and what was used instead
};

/// The material thermometers: the specification's, else up to three channels
/// of role `structure`. An id that is not a temperature channel of the
/// campaign is an error naming it.
QStringList materialChannels(const Campaign& campaign, const TemperatureSetting& setting,
                             QString* error);

/// The air and material temperatures during `run`'s positioning readings.
TestEnvironment testEnvironment(const Campaign& campaign, const Run& run,
                                const QStringList& materialChannels);

struct Normalisation {
    enum class Mode { Normalised, MachineCompensates, NotNormalised };
    Mode mode = Mode::NotNormalised;
    double expansion_per_K = 0;
    double mean_material_C = 20;       ///< over the readings
    double largest_correction_um = 0;  ///< the largest |α·(θ − 20)·P| taken out
    /// What was done, in a sentence for the report.
    QString description;
};

/// `run`'s readings brought to 20 °C as `setting` asks: each reading x at
/// position P corrected by −α·(θ − 20 °C)·P, θ the mean of the material
/// thermometers at the reading's time (interpolated between samples), or the
/// specification's fixed material temperature when none was logged. The
/// position reference is the machine's zero: a different one shifts every
/// deviation alike and leaves every ISO 230-2 value unchanged.
/// Returns nullopt with `error` when normalising needs a temperature there is not.
std::optional<std::vector<Reading>> readingsAt20C(const Campaign& campaign, const Run& run,
                                                  const TemperatureSetting& setting,
                                                  const QStringList& materialChannels,
                                                  Normalisation* normalisation, QString* error);

}  // namespace driftlab::iso
