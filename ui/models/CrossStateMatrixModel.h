#pragma once
// The cross-state matrix of every model as one coloured table: a row per
// (model, training run), a column per run scored, RMS in µm. Green is the
// smallest RMS of the whole table, red the largest (log scale: the cells span
// two decades). The diagonal is the training score, shown in brackets.

#include <QAbstractTableModel>
#include <QColor>
#include <utility>
#include <vector>

#include "core/models/ModelScore.h"

namespace driftlab::ui {

class CrossStateMatrixModel : public QAbstractTableModel {
    Q_OBJECT
public:
    /// Qt::UserRole of a cell: the RMS in µm (NaN where the fit or score failed).
    static constexpr int kRmsRole = Qt::UserRole;

    explicit CrossStateMatrixModel(QObject* parent = nullptr);

    void setMatrices(const QStringList& runs,
                     std::vector<std::pair<QString, models::CrossStateMatrix>> matrices);
    void clear();

    /// The colour of `rms_um` on the green (min) → red (max) log scale.
    static QColor rmsColour(double rms_um, double min_um, double max_um);
    double minimumRms() const { return m_min_um; }
    double maximumRms() const { return m_max_um; }
    /// Error lines of every model, "model: line".
    QStringList errors() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Row {
        QString model, trainRun;
        std::size_t matrix = 0, index = 0;
    };
    double cell(int row, int column) const;

    QStringList m_runs;
    std::vector<std::pair<QString, models::CrossStateMatrix>> m_matrices;
    std::vector<Row> m_rows;
    double m_min_um = 0, m_max_um = 0;
};

}  // namespace driftlab::ui
