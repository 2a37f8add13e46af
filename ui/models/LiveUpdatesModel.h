#pragma once
// The updates a live compensation run applied, one row each: when it fell due
// and when it was applied (later when it waited for a cut to end), the offset
// sent, the model's prediction with its 95 % uncertainty, and what the change
// limit held back.

#include <QAbstractTableModel>
#include <vector>

#include "core/compensation/LiveThermalCompensation.h"

namespace driftlab::ui {

class LiveUpdatesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Time, Due, Offset, Prediction, HeldBack, Note, ColumnCount };

    explicit LiveUpdatesModel(QObject* parent = nullptr);

    /// Starts a new run: no rows, `uncertainty_um` for its predictions (NaN: not known).
    void reset(double uncertainty_um);
    void append(const compensation::LiveUpdate& update);

    const std::vector<compensation::LiveUpdate>& updates() const { return m_updates; }
    double uncertaintyUm() const { return m_uncertainty_um; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<compensation::LiveUpdate> m_updates;
    double m_uncertainty_um = 0;
};

}  // namespace driftlab::ui
