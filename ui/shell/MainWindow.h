#pragma once
// The main window (docs/gui-setup.md): the campaign tree in a dock on the
// left, the pages as tabs in the centre (Set-up, Run, Models, Diagnosis,
// Compensation, ISO 230-2), the event log in a dock below, run control in a
// tool bar and the run state in the status bar; a bundle folder or .zip
// dropped on the window is imported (docs/gui-data.md). Window layout, the last
// store and the recent stores persist with QSettings.

#include <QMainWindow>

class QTabWidget;
class QTreeView;
class QMenu;

namespace driftlab::ui {

class Session;
class CampaignTreeModel;
class EventLogModel;
class SetupPage;
class RunPage;
class ModelsPage;
class DiagnosisPage;
class CompensationPage;
class LiveCompensationPage;
class Iso230_2Page;
class Iso230_3Page;
class SensorHealthPage;
class ReportExport;
class CampaignImportFlow;
class CampaignExportFlow;
class InterferometerCsvDialog;
class LabStoreDialog;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Session& session() { return *m_session; }
    QTabWidget* pages() const { return m_tabs; }
    EventLogModel* eventLog() const { return m_events; }
    CampaignTreeModel* campaignTree() const { return m_tree; }
    SetupPage* setupPage() const { return m_setup; }
    RunPage* runPage() const { return m_run; }
    ModelsPage* modelsPage() const { return m_models; }
    DiagnosisPage* diagnosisPage() const { return m_diagnosis; }
    CompensationPage* compensationPage() const { return m_compensation; }
    LiveCompensationPage* liveCompensationPage() const { return m_live; }
    Iso230_2Page* iso230_2Page() const { return m_iso; }
    Iso230_3Page* iso230_3Page() const { return m_iso3; }
    SensorHealthPage* sensorHealthPage() const { return m_health; }
    /// File → Export report…: the acceptance report of the selected campaign.
    ReportExport* reportExport() const { return m_report; }
    /// File → Import campaign… and bundles dropped on the window.
    CampaignImportFlow* importFlow() const { return m_import; }
    /// The column mapping of an interferometer CSV export being imported.
    InterferometerCsvDialog* interferometerCsvDialog() const { return m_csvDialog; }
    /// File → Export campaign…: the selected campaign as a bundle folder.
    CampaignExportFlow* exportFlow() const { return m_export; }
    /// File → Open lab store…: a postgresql:// store and its spool.
    LabStoreDialog* labStoreDialog() const { return m_labStore; }

    /// Opens a store (creating it when `create`); errors go to the event log
    /// and, with `tellUser`, to a message box.
    bool openStore(const QString& path, bool create, bool tellUser = true);

public slots:
    /// The demo: a new store with the simulated rig set up, ready to run.
    void startDemo();
    void refreshCampaignTree();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildMenus();
    void buildDocks();
    void rememberStore(const QString& path);
    void updateRecentMenu();
    void exportReport();
    void importCampaign(const QString& path);
    void chooseCampaignToImport();
    void exportCampaign();

    Session* m_session;
    CampaignTreeModel* m_tree;
    EventLogModel* m_events;
    QTabWidget* m_tabs;
    QTreeView* m_treeView = nullptr;
    QMenu* m_recent = nullptr;
    SetupPage* m_setup;
    RunPage* m_run;
    ModelsPage* m_models;
    DiagnosisPage* m_diagnosis;
    CompensationPage* m_compensation;
    LiveCompensationPage* m_live;
    Iso230_2Page* m_iso;
    Iso230_3Page* m_iso3;
    SensorHealthPage* m_health;
    ReportExport* m_report;
    CampaignImportFlow* m_import;
    InterferometerCsvDialog* m_csvDialog;
    CampaignExportFlow* m_export;
    LabStoreDialog* m_labStore;
};

}  // namespace driftlab::ui
