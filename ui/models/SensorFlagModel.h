#pragma once
// The sensor-health page's table: the stored flags of one run, one row per
// flagged stretch (channel, kind, from–to, samples) and whether the models
// leave its samples out or the user kept them. Display text is rounded;
// Qt::UserRole gives the number, and on the first column the flag's row id.

#include <QAbstractTableModel>
#include <vector>

#include "ui/shell/SensorFlagJob.h"

namespace driftlab::ui {

class SensorFlagModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Channel, Kind, From, To, Samples, InFits };

    explicit SensorFlagModel(QObject* parent = nullptr);

    void setFlags(std::vector<ShownFlag> flags);
    const std::vector<ShownFlag>& flags() const { return m_flags; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<ShownFlag> m_flags;
};

}  // namespace driftlab::ui
