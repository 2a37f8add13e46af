#pragma once
// The Live compensation page (docs/live-compensation.md, "In the desktop
// application"): the heat-transfer model fitted on training runs drives a
// stored run replayed as live data, as `driftlab-cli live` does, with the
// same service (acquisition/live/LiveCompensationService). Without a
// controller it is a rehearsal; with one (LinuxCNC's external offsets through
// driftlab_eoffset, or a PLC's Modbus live-offset registers) each update is
// written to it and the machine state is read from it. The loop runs on a
// worker and can be stopped; each update shows in a plot and a table against
// the model's prediction and its band. A model worse than no compensation is
// refused for a controller unless the override is ticked.

#include <QWidget>
#include <optional>

#include "acquisition/live/LiveCompensationService.h"
#include "ui/widgets/CampaignLoad.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;
class QTableView;

namespace driftlab::ui {

class BackgroundJob;
class LiveOffsetPlot;
class LiveUpdatesModel;
class SelectedCampaignLoader;
class Session;

class LiveCompensationPage : public QWidget {
    Q_OBJECT
public:
    /// Where the offsets go.
    enum Controller { Rehearsal, LinuxCnc, ModbusRegisters };

    explicit LiveCompensationPage(Session& session, QWidget* parent = nullptr);
    ~LiveCompensationPage() override;

    QComboBox* modelBox() const { return m_model; }
    QComboBox* runBox() const { return m_run; }
    QListWidget* trainList() const { return m_train; }
    QDoubleSpinBox* intervalBox() const { return m_interval; }
    QDoubleSpinBox* changeLimitBox() const { return m_maxChange; }
    QComboBox* controllerBox() const { return m_controller; }
    QLineEdit* urlEdit() const { return m_url; }
    QDoubleSpinBox* speedupBox() const { return m_speedup; }
    QCheckBox* overrideBox() const { return m_override; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* stopButton() const { return m_stop; }
    /// The no-harm line: why the model is refused (or would be), hidden when it is not.
    QLabel* harmLabel() const { return m_harm; }
    /// The cut gate: the machine state now and whether updates are held.
    QLabel* gateLabel() const { return m_gate; }
    /// What the run did, or why it failed.
    QLabel* statusLabel() const { return m_status; }
    LiveUpdatesModel* updatesModel() const { return m_updates; }
    LiveOffsetPlot* plot() const { return m_plot; }
    bool isRunning() const;

signals:
    /// The campaign is loaded and its runs are listed.
    void campaignShown();
    /// An update was applied and shown (its row in updatesModel()).
    void updateShown();
    /// A run ended: finished, stopped, refused or failed (see statusLabel()).
    void runFinished();

public slots:
    void start();
    void stop();

private:
    void onLoaded(const LoadedCampaign& loaded);
    void clearCampaign();
    /// heat-transfer and the campaign's adopted `extensions` (newest first).
    void fillModels(const QStringList& extensions);
    void fillTrainRuns();
    void updateControllerFields();
    void updateButtons();
    void showPlan(const live::LivePlan& plan);
    void showState(double time_s, MachineState state);
    void showUpdate(const compensation::LiveUpdate& update);
    void showError(const QString& message);
    live::LiveCompensationOptions options(QString* error) const;

    Session& m_session;
    QComboBox* m_model;
    QComboBox* m_run;
    QListWidget* m_train;
    QDoubleSpinBox* m_interval;
    QDoubleSpinBox* m_maxChange;
    QSpinBox* m_points;
    QComboBox* m_controller;
    QLineEdit* m_url;
    QSpinBox* m_staleAfter;
    QDoubleSpinBox* m_speedup;
    QCheckBox* m_override;
    QPushButton* m_start;
    QPushButton* m_stop;
    QLabel* m_harm;
    QLabel* m_gate;
    QLabel* m_status;
    QTableView* m_view;
    LiveUpdatesModel* m_updates;
    LiveOffsetPlot* m_plot;
    SelectedCampaignLoader* m_loader;
    BackgroundJob* m_job;
    std::optional<Campaign> m_campaign;
    std::optional<double> m_cutSince_s;  ///< the machine cuts since then
    double m_lastTime_s = 0;
};

}  // namespace driftlab::ui
