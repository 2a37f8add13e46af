#include "ui/models/CampaignTreeModel.h"

#include <QJsonObject>

namespace driftlab::ui {

CampaignTreeModel::CampaignTreeModel(QObject* parent) : QAbstractItemModel(parent) {}
CampaignTreeModel::~CampaignTreeModel() = default;

void CampaignTreeModel::setOverview(const std::vector<db::CampaignOverview>& campaigns) {
    beginResetModel();
    m_root.children.clear();
    for (const auto& c : campaigns) {
        auto campaign = std::make_unique<Node>();
        campaign->kind = ItemKind::Campaign;
        campaign->id = campaign->campaign_id = c.id;
        campaign->name = c.name;
        campaign->detail = tr("campaign %1, %n run(s)", nullptr, int(c.runs.size())).arg(c.id);
        campaign->parent = &m_root;
        auto add = [&](ItemKind kind, qint64 id, const QString& name, const QString& detail) {
            auto node = std::make_unique<Node>();
            *node = {kind, id, c.id, name, detail, campaign.get(), {}};
            campaign->children.push_back(std::move(node));
        };
        for (const auto& r : c.runs)
            add(ItemKind::Run, r.id, r.name,
                tr("%1, %2, %3 rows, %4 readings")
                    .arg(r.kind, r.status)
                    .arg(r.rows)
                    .arg(r.readings));
        for (const auto& f : c.fits) {
            const double rms = f.metrics.value(QStringLiteral("test"))
                                   .toObject()
                                   .value(QStringLiteral("rms_um"))
                                   .toDouble(-1);
            add(ItemKind::Fit, f.id, tr("fit %1: %2").arg(f.id).arg(f.model),
                tr("trained on %1%2")
                    .arg(f.train_runs.join(QStringLiteral(", ")),
                         rms >= 0 ? tr(", held-out RMS %1 µm").arg(rms, 0, 'f', 2) : QString()));
        }
        for (const auto& d : c.diagnoses)
            add(ItemKind::Diagnosis, d.id, tr("diagnosis %1").arg(d.id),
                tr("%1: %2").arg(d.base_model, d.verdict));
        for (const auto& p : c.pushes)
            add(ItemKind::Push, p.id, tr("push %1: %2").arg(p.id).arg(p.result),
                tr("%1 points to %2 at %3").arg(p.points).arg(p.controller_url, p.pushed_at));
        m_root.children.push_back(std::move(campaign));
    }
    endResetModel();
}

const CampaignTreeModel::Node* CampaignTreeModel::nodeOf(const QModelIndex& index) const {
    return index.isValid() ? static_cast<const Node*>(index.internalPointer()) : &m_root;
}

QModelIndex CampaignTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= 2 || (parent.isValid() && parent.column() != 0)) return {};
    const Node* p = nodeOf(parent);
    if (row < 0 || row >= int(p->children.size())) return {};
    return createIndex(row, column, p->children[std::size_t(row)].get());
}

QModelIndex CampaignTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid()) return {};
    const Node* p = nodeOf(child)->parent;
    if (!p || p == &m_root) return {};
    const auto& siblings = p->parent->children;
    for (std::size_t i = 0; i < siblings.size(); ++i)
        if (siblings[i].get() == p) return createIndex(int(i), 0, const_cast<Node*>(p));
    return {};
}

int CampaignTreeModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() && parent.column() != 0) return 0;
    return int(nodeOf(parent)->children.size());
}

int CampaignTreeModel::columnCount(const QModelIndex&) const {
    return 2;
}

QVariant CampaignTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const Node* n = nodeOf(index);
    switch (role) {
        case Qt::DisplayRole:
            return index.column() == 0 ? n->name : n->detail;
        case Qt::ToolTipRole:
            return n->detail;
        case KindRole:
            return int(n->kind);
        case IdRole:
            return n->id;
        case CampaignIdRole:
            return n->campaign_id;
        default:
            return {};
    }
}

QVariant CampaignTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    return section == 0 ? tr("Name") : tr("What");
}

QModelIndex CampaignTreeModel::campaignIndex(qint64 campaignId) const {
    for (std::size_t i = 0; i < m_root.children.size(); ++i)
        if (m_root.children[i]->id == campaignId)
            return createIndex(int(i), 0, m_root.children[i].get());
    return {};
}

}  // namespace driftlab::ui
