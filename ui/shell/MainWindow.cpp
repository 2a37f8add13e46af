#include "ui/shell/MainWindow.h"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QTreeView>

#include "db/CampaignStore.h"
#include "db/StoreBackend.h"
#include "db/StoreOverview.h"
#include "ui/models/CampaignTreeModel.h"
#include "ui/models/EventLogModel.h"
#include "ui/pages/CompensationPage.h"
#include "ui/pages/DiagnosisPage.h"
#include "ui/pages/Iso230_2Page.h"
#include "ui/pages/Iso230_3Page.h"
#include "ui/pages/LiveCompensationPage.h"
#include "ui/pages/ModelsPage.h"
#include "ui/pages/RunPage.h"
#include "ui/pages/SensorHealthPage.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/CampaignExportFlow.h"
#include "ui/shell/CampaignImportFlow.h"
#include "ui/shell/ReportExport.h"
#include "ui/shell/Session.h"
#include "ui/widgets/InterferometerCsvDialog.h"
#include "ui/widgets/LabStoreDialog.h"

namespace driftlab::ui {
namespace {
const QString kRecentKey = QStringLiteral("stores/recent");
const QString kLastKey = QStringLiteral("stores/last");
constexpr int kRecentCount = 8;

/// A store as the window names it: a lab store's URL without its password
/// (~/.pgpass holds that), a file as its path.
QString shownStoreName(const QString& location) {
    const auto server =
        db::isServerStoreUrl(location) ? db::parseServerStoreUrl(location, nullptr) : std::nullopt;
    return server ? server->display() : location;
}
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_session(new Session(this)),
      m_tree(new CampaignTreeModel(this)),
      m_events(new EventLogModel(10'000, this)),
      m_tabs(new QTabWidget(this)) {
    setWindowTitle(tr("DriftLab"));
    setObjectName(QStringLiteral("MainWindow"));
    m_setup = new SetupPage(*m_session, m_tabs);
    m_run = new RunPage(*m_session, m_tabs);
    m_models = new ModelsPage(*m_session, m_tabs);
    m_diagnosis = new DiagnosisPage(*m_session, m_tabs);
    m_compensation = new CompensationPage(*m_session, m_tabs);
    m_live = new LiveCompensationPage(*m_session, m_tabs);
    m_iso = new Iso230_2Page(*m_session, m_tabs);
    m_iso3 = new Iso230_3Page(*m_session, m_tabs);
    m_health = new SensorHealthPage(*m_session, m_tabs);
    m_report = new ReportExport(*m_session, this);
    m_import = new CampaignImportFlow(*m_session, this);
    m_csvDialog = new InterferometerCsvDialog(this);
    connect(m_csvDialog, &QDialog::accepted, this, [this] {
        QString why;
        if (!m_import->startInterferometerCsv(m_csvDialog->request(), &why)) {
            m_events->append(QStringLiteral("error"), QStringLiteral("import"),
                             tr("%1 not imported: %2").arg(m_csvDialog->request().path, why));
            QMessageBox::warning(this, tr("Campaign not imported"), why);
        }
    });
    m_export = new CampaignExportFlow(*m_session, this);
    m_labStore =
        new LabStoreDialog([this](const QString& url) { return openStore(url, false); }, this);
    setAcceptDrops(true);
    m_tabs->addTab(m_setup, tr("Set-up"));
    m_tabs->addTab(m_run, tr("Run"));
    m_tabs->addTab(m_models, tr("Models"));
    m_tabs->addTab(m_diagnosis, tr("Diagnosis"));
    m_tabs->addTab(m_compensation, tr("Compensation"));
    m_tabs->addTab(m_live, tr("Live"));
    m_tabs->addTab(m_iso, tr("ISO 230-2"));
    m_tabs->addTab(m_iso3, tr("ISO 230-3"));
    m_tabs->addTab(m_health, tr("Sensor health"));
    setCentralWidget(m_tabs);
    buildDocks();
    buildMenus();

    auto* runBar = addToolBar(tr("Run control"));
    runBar->setObjectName(QStringLiteral("RunControl"));
    runBar->addActions(m_run->runActions());
    statusBar()->addPermanentWidget(m_run->statusWidget(), 1);

    connect(m_session, &Session::event, m_events, &EventLogModel::append);
    connect(m_session, &Session::storeChanged, this, [this](const QString& path) {
        setWindowTitle(tr("DriftLab — %1").arg(shownStoreName(path)));
        refreshCampaignTree();
    });
    connect(m_session, &Session::storeContentChanged, this, &MainWindow::refreshCampaignTree);

    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray()))
        resize(1280, 800);  // the smallest screen the window is made for
    if (!restoreState(settings.value(QStringLiteral("window/state")).toByteArray())) {
        // The pages get the room: a narrow tree, a short log.
        resizeDocks({findChild<QDockWidget*>(QStringLiteral("CampaignsDock"))}, {280},
                    Qt::Horizontal);
        resizeDocks({findChild<QDockWidget*>(QStringLiteral("EventsDock"))}, {150}, Qt::Vertical);
    }
    updateRecentMenu();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildDocks() {
    m_treeView = new QTreeView(this);
    m_treeView->setModel(m_tree);
    m_treeView->setObjectName(QStringLiteral("CampaignTree"));
    m_treeView->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    connect(m_treeView->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid())
                    m_session->selectCampaign(
                        current.data(CampaignTreeModel::CampaignIdRole).toLongLong());
            });
    auto* treeDock = new QDockWidget(tr("Campaigns"), this);
    treeDock->setObjectName(QStringLiteral("CampaignsDock"));
    treeDock->setWidget(m_treeView);
    addDockWidget(Qt::LeftDockWidgetArea, treeDock);

    auto* log = new QTableView(this);
    log->setModel(m_events);
    log->setObjectName(QStringLiteral("EventLog"));
    log->horizontalHeader()->setStretchLastSection(true);
    log->verticalHeader()->hide();
    connect(m_events, &QAbstractItemModel::rowsInserted, log, [log] { log->scrollToBottom(); });
    auto* logDock = new QDockWidget(tr("Events"), this);
    logDock->setObjectName(QStringLiteral("EventsDock"));
    logDock->setWidget(log);
    addDockWidget(Qt::BottomDockWidgetArea, logDock);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New store…"), QKeySequence::New, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("New campaign store"), {},
                                                          tr("DriftLab stores (*.sqlite)"));
        if (!path.isEmpty()) openStore(path, true);
    });
    file->addAction(tr("&Open store…"), QKeySequence::Open, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open campaign store"), {},
                                                          tr("DriftLab stores (*.sqlite)"));
        if (!path.isEmpty()) openStore(path, false);
    });
    QAction* lab = file->addAction(tr("Open &lab store…"), this, [this] {
        m_labStore->show();
        m_labStore->raise();
    });
    lab->setObjectName(QStringLiteral("OpenLabStoreAction"));
    m_recent = file->addMenu(tr("Recent stores"));
    file->addSeparator();
    QAction* import = file->addAction(tr("&Import campaign…"), QKeySequence(Qt::CTRL | Qt::Key_I),
                                      this, &MainWindow::chooseCampaignToImport);
    import->setObjectName(QStringLiteral("ImportCampaignAction"));
    QAction* exportBundle =
        file->addAction(tr("Export &campaign…"), this, &MainWindow::exportCampaign);
    exportBundle->setObjectName(QStringLiteral("ExportCampaignAction"));
    exportBundle->setEnabled(false);
    connect(m_session, &Session::campaignSelected, exportBundle,
            [exportBundle](std::optional<qint64> id) { exportBundle->setEnabled(id.has_value()); });
    connect(m_export, &CampaignExportFlow::finished, this,
            [this](bool written, const QString& message) {
                statusBar()->showMessage(written ? tr("Campaign exported: %1").arg(message)
                                                 : tr("Campaign not exported: %1").arg(message),
                                         10'000);
            });
    QAction* report = file->addAction(tr("&Export report…"), this, &MainWindow::exportReport);
    report->setObjectName(QStringLiteral("ExportReportAction"));
    report->setEnabled(false);
    connect(m_session, &Session::campaignSelected, report,
            [report](std::optional<qint64> id) { report->setEnabled(id.has_value()); });
    // Not a message box: the event log has it, and an export must not block the window.
    connect(m_report, &ReportExport::finished, this, [this](bool written, const QString& message) {
        statusBar()->showMessage(written ? tr("Report written: %1").arg(message)
                                         : tr("Report not written: %1").arg(message),
                                 10'000);
    });
    file->addSeparator();
    file->addAction(tr("Run the &demo"), this, &MainWindow::startDemo);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        view->addAction(dock->toggleViewAction());
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About DriftLab"), this, [this] {
        QMessageBox::about(this, tr("About DriftLab"),
                           tr("DriftLab: thermal test campaigns on machine-tool feed axes."));
    });
}

bool MainWindow::openStore(const QString& path, bool create, bool tellUser) {
    QString error;
    if (!m_session->openStore(path, create, &error)) {
        m_events->append(QStringLiteral("error"), QStringLiteral("store"), error);
        if (tellUser) QMessageBox::warning(this, tr("Store not opened"), error);
        return false;
    }
    rememberStore(shownStoreName(m_session->storePath()));
    return true;
}

void MainWindow::refreshCampaignTree() {
    if (m_session->storePath().isEmpty()) return;
    QString error;
    auto store = db::CampaignStore::open(m_session->storePath(), db::StoreAccess::ReadOnly, &error);
    const auto overview = store ? db::storeOverview(*store, &error) : std::nullopt;
    if (!overview) {
        m_events->append(QStringLiteral("error"), QStringLiteral("store"), error);
        return;
    }
    m_tree->setOverview(*overview);
    m_treeView->expandAll();
    if (const auto id = m_session->campaignId())
        m_treeView->setCurrentIndex(m_tree->campaignIndex(*id));
}

void MainWindow::rememberStore(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(kRecentKey).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kRecentCount) recent.removeLast();
    settings.setValue(kRecentKey, recent);
    settings.setValue(kLastKey, path);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    m_recent->clear();
    for (const QString& path : QSettings().value(kRecentKey).toStringList())
        m_recent->addAction(path, this, [this, path] { openStore(path, false); });
    m_recent->setEnabled(!m_recent->isEmpty());
}

void MainWindow::exportReport() {
    if (!m_session->campaignId()) return;
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export acceptance report"), {}, tr("PDF (*.pdf)"));
    if (!path.isEmpty()) m_report->start(path);
}

void MainWindow::chooseCampaignToImport() {
    // One dialog for both forms of a bundle: its .zip, or the campaign.json
    // that names its folder (a file dialog picks files or folders, not both);
    // and for an interferometer's CSV export, mapped in its own dialog next.
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import campaign"), {},
        tr("Campaign bundles and interferometer exports (*.zip campaign.json *.csv);;Bundle "
           "archives (*.zip);;Bundle folders (campaign.json);;Interferometer CSV exports "
           "(*.csv)"));
    if (path.isEmpty()) return;
    const QFileInfo chosen(path);
    importCampaign(chosen.fileName() == QLatin1String("campaign.json") ? chosen.absolutePath()
                                                                       : path);
}

void MainWindow::importCampaign(const QString& path) {
    if (CampaignImportFlow::isInterferometerCsv(path)) {
        // Its columns are the vendor's: the user maps them first (window-modal,
        // the window's event loop goes on).
        m_csvDialog->load(path);
        m_csvDialog->open();
        return;
    }
    QString why;
    if (!m_import->start(path, &why)) {
        m_events->append(QStringLiteral("error"), QStringLiteral("import"),
                         tr("%1 not imported: %2").arg(path, why));
        QMessageBox::warning(this, tr("Campaign not imported"), why);
    }
}

void MainWindow::exportCampaign() {
    const auto id = m_session->campaignId();
    if (!id) return;
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export campaign as a bundle folder (new or empty)"),
                                     QStringLiteral("campaign-%1").arg(*id));
    if (!path.isEmpty()) m_export->start(path);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (CampaignImportFlow::bundleOf(event->mimeData())) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto path = CampaignImportFlow::bundleOf(event->mimeData());
    if (!path) return;
    event->acceptProposedAction();
    importCampaign(*path);
}

void MainWindow::startDemo() {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(dir);
    if (!openStore(QDir(dir).filePath(QStringLiteral("demo.sqlite")), true)) return;
    m_setup->loadDemo();
    m_tabs->setCurrentWidget(m_setup);
    m_events->append(QStringLiteral("info"), QStringLiteral("demo"),
                     tr("demo store opened: set up with the simulated rig; press Start on the "
                        "Run page"));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

}  // namespace driftlab::ui
