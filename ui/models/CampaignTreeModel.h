#pragma once
// The campaign tree (left dock): campaigns, and under each its runs, fits,
// diagnoses and compensation pushes. Built from a db::storeOverview()
// snapshot; two columns, the name and what it is.

#include <QAbstractItemModel>
#include <memory>
#include <vector>

#include "db/StoreOverview.h"

namespace driftlab::ui {

class CampaignTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum class ItemKind { Campaign, Run, Fit, Diagnosis, Push };
    enum Role { KindRole = Qt::UserRole + 1, IdRole, CampaignIdRole };

    explicit CampaignTreeModel(QObject* parent = nullptr);
    ~CampaignTreeModel() override;

    void setOverview(const std::vector<db::CampaignOverview>& campaigns);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    /// The campaign row of `campaignId`, or an invalid index.
    QModelIndex campaignIndex(qint64 campaignId) const;

private:
    struct Node {
        ItemKind kind = ItemKind::Campaign;
        qint64 id = 0;
        qint64 campaign_id = 0;
        QString name, detail;
        Node* parent = nullptr;
        std::vector<std::unique_ptr<Node>> children;
    };
    const Node* nodeOf(const QModelIndex& index) const;
    Node m_root;
};

}  // namespace driftlab::ui
