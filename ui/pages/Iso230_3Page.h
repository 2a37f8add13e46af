#pragma once
// The ISO 230-3 page (docs/gui-iso230-3.md, docs/iso230-3.md): a run of the
// selected campaign evaluated as `driftlab-cli iso230-3` does, with the
// stabilisation criterion (W, D) and the spindle probe distance editable as
// its options. A moving run shows the drift of each target and direction
// over time and the drift map over position × time; a spindle or ETVE run its
// five probes, the tilts when the probe distance is given, and its
// temperatures. The evaluation runs on a worker.

#include <QWidget>
#include <memory>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/iso/Iso230_3Json.h"
#include "ui/widgets/CampaignLoad.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableView;

namespace driftlab::ui {

class BackgroundJob;
class DriftSeriesModel;
class Iso230_3Plot;
class SelectedCampaignLoader;
class Session;

class Iso230_3Page : public QWidget {
    Q_OBJECT
public:
    explicit Iso230_3Page(Session& session, QWidget* parent = nullptr);
    ~Iso230_3Page() override;

    /// The runs with drift to evaluate: moving-axis runs with positioning
    /// readings, spindle and ETVE runs.
    QComboBox* runBox() const { return m_run; }
    /// W (s) and D (µm) of the criterion; the probe distance L (mm, 0 = not given).
    QDoubleSpinBox* windowBox() const { return m_window; }
    QDoubleSpinBox* toleranceBox() const { return m_tolerance; }
    QDoubleSpinBox* probeDistanceBox() const { return m_distance; }
    DriftSeriesModel* seriesModel() const { return m_model; }
    Iso230_3Plot* plot() const { return m_plot; }
    QLabel* messageLabel() const { return m_message; }
    /// The run's figures: maximum drift and when, stabilisation.
    QLabel* summaryLabel() const { return m_summary; }
    /// The evaluation shown (nullopt before one, or when it failed).
    const std::optional<iso::RunDrift>& drift() const { return m_drift; }

signals:
    /// An evaluation has been shown (or its failure).
    void evaluated();

private:
    void onLoaded(const LoadedCampaign& loaded);
    void evaluateRun();
    void showDrift(const Run& run, iso::RunDrift drift);
    void showError(const QString& message);

    Session& m_session;
    QComboBox* m_run;
    QDoubleSpinBox* m_window;
    QDoubleSpinBox* m_tolerance;
    QDoubleSpinBox* m_distance;
    QLabel* m_message;
    QLabel* m_summary;
    QLabel* m_warnings;
    QTableView* m_view;
    DriftSeriesModel* m_model;
    Iso230_3Plot* m_plot;
    BackgroundJob* m_job;
    SelectedCampaignLoader* m_loader;
    /// Shared with the worker, which reads it while the page may load another.
    std::shared_ptr<const Campaign> m_campaign;
    std::optional<iso::RunDrift> m_drift;
    /// A setting changed while an evaluation ran: evaluate again when it ends.
    bool m_evaluateAgain = false;
};

}  // namespace driftlab::ui
