#pragma once
// The machine history of a store (docs/history.md): every campaign of one
// machine and axis (campaign.json machine.name and machine.axis), loaded and
// evaluated, in the order of its date (the date campaign.json records, else
// the time it was stored).

#include <QString>
#include <optional>
#include <vector>

#include "core/history/MachineHistory.h"
#include "db/CampaignStore.h"

namespace driftlab::db {

/// A machine and axis of the store, with how many campaigns it has.
struct MachineAxis {
    QString machine;
    QString axis;
    int campaigns = 0;
};

/// Every machine and axis the store holds, sorted; nullopt with `error`.
std::optional<std::vector<MachineAxis>> machineAxes(CampaignStore& store, QString* error);

/// The history of `machine` and `axis` (exact, case-sensitive as campaign.json
/// writes them). Nullopt with `error` when a campaign cannot be read, or when
/// none matches: the error then lists the machines and axes the store has.
std::optional<history::MachineHistory> machineHistory(CampaignStore& store, const QString& machine,
                                                      const QString& axis,
                                                      const history::HistorySettings& settings = {},
                                                      QString* error = nullptr);

}  // namespace driftlab::db
