#pragma once
// The score of a fitted model per test run: RMS and peak of measured −
// predicted, the uncompensated RMS and the share removed (reduction).

#include <QAbstractTableModel>
#include <vector>

#include "core/models/ModelScore.h"

namespace driftlab::ui {

class TestScoresModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Run, Rms, Peak, Uncompensated, Reduction, ColumnCount };
    struct Row {
        QString run;  ///< a run id, or "all" for the pooled score
        models::Score score;
    };
    explicit TestScoresModel(QObject* parent = nullptr);

    void setRows(std::vector<Row> rows);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<Row> m_rows;
};

}  // namespace driftlab::ui
