#pragma once
// Runs the items of `driftlab-cli batch`, each in a child process of this
// same executable (`driftlab-cli batch-item`), N at a time. A child that
// crashes, hangs past its time limit or runs out of memory fails its own item
// and no other, and Ceres and glog never run two campaigns in one process.

#include <QJsonObject>
#include <QStringList>
#include <functional>
#include <optional>
#include <vector>

#include "app/cli/BatchItems.h"

namespace driftlab::cli {

struct BatchRunOptions {
    int jobs = 1;                     ///< child processes at once
    double timeout_s = 3600;          ///< an item running longer is killed and failed
    std::optional<double> memory_mb;  ///< address-space limit of each child
    QStringList itemArguments;        ///< for each child after its source (--what …)
};

/// An item's JSON line: "item", "ok", "seconds", then the child's result
/// (name, runs, one key per analysis) and, when it failed, "error" (one line).
using ItemFinished = std::function<void(std::size_t index, const QJsonObject& line)>;

/// Runs `items` (an item with an error is reported at once, without a child)
/// and calls `finished` for each in the order they finish; returns when all
/// have. Runs an event loop of its own.
void runBatch(const std::vector<BatchItem>& items, const BatchRunOptions& options,
              const ItemFinished& finished);

}  // namespace driftlab::cli
