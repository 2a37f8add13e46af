#pragma once
// The findings of a diagnosis, best held-out gain first: the cause, whether
// it is significant, the gain on the held-out runs, ΔBIC on the training runs,
// the extension's parameter ± σ and the evidence in words.

#include <QAbstractTableModel>
#include <vector>

#include "core/diagnosis/Diagnosis.h"

namespace driftlab::ui {

class FindingsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Cause,
        Significant,
        Confidence,
        Gain,
        RmsAfter,
        BicDrop,
        Parameter,
        Evidence,
        ColumnCount
    };
    explicit FindingsModel(QObject* parent = nullptr);

    /// `verdict`: the cause the diagnosis named (its row is bold).
    void setFindings(std::vector<diagnosis::Finding> findings, const QString& verdict);
    const diagnosis::Finding* finding(int row) const;
    /// The row of the verdict's finding, or −1.
    int verdictRow() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<diagnosis::Finding> m_findings;
    QString m_verdict;
};

}  // namespace driftlab::ui
