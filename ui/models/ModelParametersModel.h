#pragma once
// The parameters of a fitted model: name, value, 1σ, unit (σ "—" when the
// data do not determine it).

#include <QAbstractTableModel>
#include <map>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::ui {

class ModelParametersModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Name, Value, Sigma, Unit, ColumnCount };
    explicit ModelParametersModel(QObject* parent = nullptr);

    void setParameters(const std::map<QString, models::Parameter>& parameters);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<std::pair<QString, models::Parameter>> m_rows;
};

}  // namespace driftlab::ui
