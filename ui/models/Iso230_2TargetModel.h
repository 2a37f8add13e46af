#pragma once
// The ISO 230-2 page's per-target table: one row per target with the
// statistics of docs/iso230.md (x̄↑, x̄↓, x̄, s↑, s↓, B_i, R↑_i, R↓_i, R_i).
// Display text has 3 decimals (µm) and "n/a" for what was not determined;
// Qt::UserRole gives the number (NaN when not determined).

#include <QAbstractTableModel>
#include <vector>

#include "core/iso/Iso230_2.h"

namespace driftlab::ui {

class Iso230_2TargetModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Target,
        CountUp,
        CountDown,
        MeanUp,
        MeanDown,
        Mean,
        SUp,
        SDown,
        Reversal,
        RUp,
        RDown,
        R,
    };

    explicit Iso230_2TargetModel(QObject* parent = nullptr);

    void setTargets(std::vector<iso::TargetResult> targets);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    double value(const iso::TargetResult& t, int column) const;
    std::vector<iso::TargetResult> m_targets;
};

}  // namespace driftlab::ui
