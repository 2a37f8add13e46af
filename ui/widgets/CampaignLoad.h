#pragma once
// Loading a campaign (and its push history) off the GUI thread: the worker
// opens its own read-only connection, as a QSqlDatabase connection may only
// be used on the thread that opened it.

#include <QFuture>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "db/PushHistory.h"

class QComboBox;

namespace driftlab::ui {

struct LoadedCampaign {
    std::optional<Campaign> campaign;  ///< nullopt with error
    QString error;
    /// The campaign's pushes, oldest first (empty when the store has no
    /// history yet); filled only when asked for.
    std::vector<db::PushRecord> pushes;
    /// The campaign's adopted extensions of heat-transfer, newest first.
    QStringList adopted_extensions;
};

/// Runs on a worker thread; `withPushes` also reads the push history.
QFuture<LoadedCampaign> loadCampaignInBackground(const QString& storePath, qint64 campaignId,
                                                 bool withPushes);

/// Fills `box` with the runs of `campaign` that have positioning readings,
/// keeping the run it showed when it is still there, else the default one
/// (iso::defaultPositioningRun); without emitting its signals.
void fillPositioningRunBox(QComboBox* box, const Campaign& campaign);

/// The push history of one campaign, read on the calling thread with its own
/// connection; empty when the store has none yet.
std::vector<db::PushRecord> campaignPushes(const QString& storePath, qint64 campaignId);

}  // namespace driftlab::ui
