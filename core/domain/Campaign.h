#pragma once
// A thermal test campaign on one feed axis: machine, screw, sensors and runs.
// Mirrors campaign.json of the bundle format (docs/bundles.md).

#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/domain/Channel.h"
#include "core/domain/Run.h"

namespace driftlab {

inline const QString kCampaignFormat = QStringLiteral("driftlab.campaign/1");

struct Machine {
    QString name;
    QString axis;
    QString controller;
    QJsonObject extra;
    bool operator==(const Machine&) const = default;
};

/// Ball screw. The fixed bearing sits at fixed_end_mm; the screw runs from there
/// towards +x for length_mm.
struct Screw {
    double length_mm = 0;
    double diameter_mm = 0;
    double lead_mm = 0;
    double fixed_end_mm = 0;
    QString mounting;  ///< fixed-free, fixed-supported or fixed-fixed
    double alpha_per_K = 11.5e-6;
    double density_kg_m3 = 7850;
    double specific_heat_J_kgK = 460;
    double conductivity_W_mK = 45;
    QJsonObject extra;
    bool operator==(const Screw&) const = default;
};

struct Interferometer {
    double dead_path_mm = 0;
    bool environment_compensation = true;
    QJsonObject extra;
    bool operator==(const Interferometer&) const = default;
};

struct Campaign {
    QString name;
    Machine machine;
    std::optional<Screw> screw;  ///< needed only for feed-axis runs
    std::optional<double> nut_length_mm;
    std::optional<RangeMm> travel_mm;
    std::optional<Interferometer> interferometer;
    std::vector<Channel> channels;
    /// Data columns of samples.csv in file order (channel ids and axis columns).
    std::vector<QString> sample_columns;
    std::vector<Run> runs;
    QJsonObject extra;  ///< top-level keys this version does not know

    const Channel* findChannel(const QString& id) const {
        for (const auto& c : channels)
            if (c.id == id) return &c;
        return nullptr;
    }
    const Run* findRun(const QString& id) const {
        for (const auto& r : runs)
            if (r.id == id) return &r;
        return nullptr;
    }
    bool operator==(const Campaign&) const = default;
};

}  // namespace driftlab
