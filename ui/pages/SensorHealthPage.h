#pragma once
// The sensor-health page (docs/sensor-health.md, "In the desktop
// application"): each run's channels with their stored flags over time
// (open/short, frozen, spikes, rate, redundancy), how many samples the models
// leave out, "Check run" (the self-diagnosis of `driftlab-cli health --store`,
// with the redundant pairs the user names)
// and keeping or masking again a flagged stretch before a fit. Every store
// access runs on a worker.

#include <QWidget>
#include <functional>
#include <memory>

#include "core/domain/Campaign.h"
#include "ui/shell/SensorFlagJob.h"
#include "ui/widgets/CampaignLoad.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;

namespace driftlab::ui {

class BackgroundJob;
class SelectedCampaignLoader;
class SensorFlagModel;
class SensorFlagTimeline;
class Session;

class SensorHealthPage : public QWidget {
    Q_OBJECT
public:
    explicit SensorHealthPage(Session& session, QWidget* parent = nullptr);
    ~SensorHealthPage() override;

    QComboBox* runBox() const { return m_run; }
    /// Redundant pairs for Check run, "A=B, C=D".
    QLineEdit* redundantPairs() const { return m_redundant; }
    QPushButton* checkButton() const { return m_check; }
    /// Keep: the selected stretches' samples go into the fits; Leave out: masked again.
    QPushButton* keepButton() const { return m_keep; }
    QPushButton* leaveOutButton() const { return m_leaveOut; }
    QTableView* flagView() const { return m_view; }
    SensorFlagModel* flagModel() const { return m_model; }
    SensorFlagTimeline* timeline() const { return m_timeline; }
    QLabel* messageLabel() const { return m_message; }
    /// The masked count: samples left out of the fits, for the run and the campaign.
    QLabel* summaryLabel() const { return m_summary; }

signals:
    /// The flags have been read and shown (or why they could not be).
    void flagsShown();

private:
    void onLoaded(const LoadedCampaign& loaded);
    void loadFlags();
    void showRun();
    void checkRun();
    void keepSelected(bool kept);
    /// Runs a store change on the worker, then tells the session (the pages refresh).
    void change(const QString& doing, std::function<QString()> work);
    void showError(const QString& message);

    Session& m_session;
    QComboBox* m_run;
    QLineEdit* m_redundant;
    QPushButton* m_check;
    QPushButton* m_keep;
    QPushButton* m_leaveOut;
    QLabel* m_message;
    QLabel* m_summary;
    QTableView* m_view;
    SensorFlagModel* m_model;
    SensorFlagTimeline* m_timeline;
    BackgroundJob* m_job;
    SelectedCampaignLoader* m_loader;
    /// Shared with the worker, which reads it while the page may load another.
    std::shared_ptr<const Campaign> m_campaign;
    qint64 m_campaignId = 0;
    CampaignFlags m_flags;
    /// The store changed while a job ran: read the flags again when it ends.
    bool m_loadAgain = false;
};

}  // namespace driftlab::ui
