#pragma once
// The rig a run is driven on, from plain options: the CLI (`run --rig …`)
// and the GUI's Run page build rigs the same way through this one function.

#include <QStringList>
#include <memory>
#include <optional>

#include "acquisition/devices/InterferometerConnection.h"
#include "acquisition/engine/TestRig.h"
#include "core/domain/Campaign.h"
#include "core/procedures/Procedure.h"

namespace driftlab::engine {

struct RigOptions {
    QString rig = QStringLiteral("sim");  ///< "sim", modbus://HOST:PORT or modbus-rtu:///dev/…
    // Simulated rig
    unsigned seed = 1;
    QStringList effects;  ///< ID=VALUE, as `simulate --effect`
    QStringList outages;  ///< RUN@FROM-TO: the temperature module does not answer then
    // Modbus rig
    QString device_map_path;     ///< the temperature module's register map
    QString controller_url;      ///< empty: no controller link
    QString interferometer_url;  ///< tcp://HOST:PORT, empty: none
    double target_tolerance_mm = 0.05;
    double poll_interval_s = 1.0;
    double connect_timeout_s = 30.0;  ///< for a device's first reading
    std::optional<Campaign> machine;  ///< machine, screw and channels of a real rig
};

/// Why a rig could not be built: the option at fault ("rig", "device-map",
/// "controller", "interferometer", "effect", "outage", …) and the reason.
struct RigError {
    QString option;
    QString message;
    QString toString() const { return option + QStringLiteral(": ") + message; }
};

/// The rig the options name; nullptr with `error` on a bad name or option.
std::unique_ptr<TestRig> makeRig(const RigOptions& options, const procedures::Procedure& procedure,
                                 RigError* error);

/// tcp://HOST:PORT of an interferometer's line stream; nullopt with `error`.
std::optional<devices::InterferometerStreamOptions> parseInterferometerUrl(const QString& text,
                                                                           QString* error);

}  // namespace driftlab::engine
