#pragma once
// Plots rendered to PNG through QCustomPlot without a window (offscreen Qt),
// for the CLI, the reports and the docs. Needs a QApplication.

#include <QSize>
#include <QString>
#include <vector>

namespace driftlab::ui {

/// A colour map z(x, y): z[iy * x.size() + ix]; x and y ascending, equally spaced.
struct MapPlot {
    QString title, xLabel, yLabel, zLabel;
    std::vector<double> x, y, z;
};

struct Curve {
    QString name;
    std::vector<double> x, y;
    bool markersOnly = false;  ///< measured points; otherwise a line
    /// The lower edge of a band whose upper edge is curve `bandOf`: drawn in
    /// its colour, the band between them shaded, no legend entry of its own.
    int bandOf = -1;
};

struct CurvePlot {
    QString title, xLabel, yLabel;
    std::vector<Curve> curves;
    /// x is seconds since 1970-01-01 UTC, labelled as dates (a machine's history).
    bool xIsDate = false;
};

/// Write the plot as PNG; false and `error` if it cannot be written or the data is inconsistent.
bool saveMapPng(const MapPlot& plot, const QString& path, QString* error, QSize size = {960, 600});
bool saveCurvesPng(const CurvePlot& plot, const QString& path, QString* error,
                   QSize size = {960, 600});

}  // namespace driftlab::ui
