#include "db/MachineHistoryStore.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <algorithm>

namespace driftlab::db {
namespace {

struct StoredCampaign {
    qint64 id = 0;
    QString machine, axis, imported_at;
};

std::optional<std::vector<StoredCampaign>> storedCampaigns(CampaignStore& store, QString* error) {
    QSqlQuery q(store.database());
    if (!q.exec(QStringLiteral("SELECT c.id, m.name, m.axis, c.imported_at FROM campaign c "
                               "JOIN machine m ON m.campaign_id = c.id ORDER BY c.id"))) {
        if (error) *error = store.path() + QStringLiteral(": ") + q.lastError().text();
        return std::nullopt;
    }
    std::vector<StoredCampaign> campaigns;
    while (q.next())
        campaigns.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                             q.value(3).toString()});
    return campaigns;
}

/// What the store holds, for the message when nothing matches.
QString holdings(const std::vector<MachineAxis>& axes) {
    if (axes.empty()) return QStringLiteral("the store holds no campaign");
    QStringList parts;
    for (const MachineAxis& a : axes)
        parts << QStringLiteral("%1 axis %2 (%3 campaign%4)")
                     .arg(a.machine, a.axis.isEmpty() ? QStringLiteral("''") : a.axis)
                     .arg(a.campaigns)
                     .arg(a.campaigns == 1 ? QString() : QStringLiteral("s"));
    return QStringLiteral("it holds: ") + parts.join(QStringLiteral("; "));
}

}  // namespace

std::optional<std::vector<MachineAxis>> machineAxes(CampaignStore& store, QString* error) {
    const auto campaigns = storedCampaigns(store, error);
    if (!campaigns) return std::nullopt;
    std::vector<MachineAxis> axes;
    for (const StoredCampaign& c : *campaigns) {
        auto it = std::find_if(axes.begin(), axes.end(), [&](const MachineAxis& a) {
            return a.machine == c.machine && a.axis == c.axis;
        });
        if (it == axes.end())
            axes.push_back({c.machine, c.axis, 1});
        else
            ++it->campaigns;
    }
    std::sort(axes.begin(), axes.end(), [](const MachineAxis& a, const MachineAxis& b) {
        return std::pair(a.machine, a.axis) < std::pair(b.machine, b.axis);
    });
    return axes;
}

std::optional<history::MachineHistory> machineHistory(CampaignStore& store, const QString& machine,
                                                      const QString& axis,
                                                      const history::HistorySettings& settings,
                                                      QString* error) {
    const auto campaigns = storedCampaigns(store, error);
    if (!campaigns) return std::nullopt;
    history::MachineHistory h{machine, axis, settings, {}};
    for (const StoredCampaign& stored : *campaigns) {
        if (stored.machine != machine || stored.axis != axis) continue;
        QString why;
        const std::optional<Campaign> campaign = store.loadCampaign(stored.id, &why);
        if (!campaign) {
            if (error) *error = QStringLiteral("campaign %1: %2").arg(stored.id).arg(why);
            return std::nullopt;
        }
        // A campaign whose campaign.json records no date is dated by its
        // import (a logged campaign: the start of its logging).
        const history::CampaignDate date =
            history::recordedDate(*campaign).value_or(history::CampaignDate{
                QDateTime::fromString(stored.imported_at, Qt::ISODateWithMs).toUTC(),
                QStringLiteral("import time")});
        h.entries.push_back(history::historyEntry(*campaign, stored.id, date, settings));
    }
    if (h.entries.empty()) {
        if (error) {
            QString ignored;
            const auto axes = machineAxes(store, &ignored);
            *error = QStringLiteral("%1: no campaign of machine '%2' axis '%3'; %4")
                         .arg(store.path(), machine, axis,
                              holdings(axes.value_or(std::vector<MachineAxis>{})));
        }
        return std::nullopt;
    }
    history::orderByDate(h.entries);
    return h;
}

}  // namespace driftlab::db
