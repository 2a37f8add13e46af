#pragma once
// The push history of a campaign (db/PushHistory.h), newest first: when, the
// run the table came from, the controller, the table version, points,
// checksum, the result (applied, rolled_back, refused, failed) and its message.

#include <QAbstractTableModel>
#include <vector>

#include "db/PushHistory.h"

namespace driftlab::ui {

class PushHistoryModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { PushedAt, Run, Controller, Version, Points, Checksum, Result, Message };

    explicit PushHistoryModel(QObject* parent = nullptr);

    /// The pushes as the store returns them (oldest first); shown newest first.
    void setPushes(std::vector<db::PushRecord> pushes);
    const db::PushRecord& push(int row) const { return m_pushes[std::size_t(row)]; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<db::PushRecord> m_pushes;  ///< newest first
};

}  // namespace driftlab::ui
