#pragma once
// The ISO 230-3 page's table: one row per drift series of a run, as
// `driftlab-cli iso230-3` lists them: each target and direction of a moving
// run, or each probe and then each tilt of a spindle or ETVE run, with its
// maximum drift and when, range, final drift and time to stabilise.
// Display text is rounded; Qt::UserRole gives the number (NaN: not stabilised).

#include <QAbstractTableModel>
#include <limits>
#include <vector>

#include "core/iso/Iso230_3Json.h"

namespace driftlab::ui {

class DriftSeriesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Series, Kind, MaxDrift, MaxDriftTime, Range, Final, Stabilised, MaxTilt };

    explicit DriftSeriesModel(QObject* parent = nullptr);

    /// The series of `drift` (empty when it has none or failed).
    void setDrift(const iso::RunDrift& drift);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Row {
        QString name;  ///< "700.000 mm" / probe id / "tilt A (X2−X1)"
        QString kind;  ///< "+" / "−" direction, the probe's role, or "tilt"
        iso::DriftSeries series;
        double max_tilt_urad = std::numeric_limits<double>::quiet_NaN();
    };
    std::vector<Row> m_rows;
    bool m_tilts = false;
};

}  // namespace driftlab::ui
