#pragma once
// The diagnoses stored for a campaign (by the GUI or `driftlab-cli diagnose
// --db`): id, verdict, runs, base RMS on the held-out runs, adopted fit.

#include <QAbstractTableModel>
#include <vector>

#include "db/DiagnosisStore.h"

namespace driftlab::ui {

class StoredDiagnosesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Id, Verdict, TrainRuns, TestRuns, BaseRms, AdoptedFit, ColumnCount };
    explicit StoredDiagnosesModel(QObject* parent = nullptr);

    void setDiagnoses(std::vector<db::DiagnosisRecord> records);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<db::DiagnosisRecord> m_records;
};

}  // namespace driftlab::ui
