// Campaigns in and out of the main window on real SQLite stores: the example
// bundle imported as a folder, as a zip (made by the real zip tool) and by a
// drop on the window; a bad bundle listed as file:line:column problems with
// the store left byte for byte as it was; a campaign exported as a bundle
// and imported again, equal to the original; an interferometer software's
// CSV export mapped in its dialog and stored as a positioning run, and a bad
// one listed by file:line:column with the store left as it was.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QCryptographicHash>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGroupBox>
#include <QLineEdit>
#include <QMimeData>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>
#include <set>

#include "db/CampaignStore.h"
#include "tests/support/VendorInterferometerCsv.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/ImportProblemsModel.h"
#include "ui/shell/CampaignExportFlow.h"
#include "ui/shell/CampaignImportFlow.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ImportProblemsDialog.h"
#include "ui/widgets/InterferometerCsvDialog.h"
#include "ui/widgets/ScrewForm.h"

using namespace driftlab;

const QString kExample =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state");

/// A main window on a new, empty store in a temporary folder.
struct DataIoFixture {
    QTemporaryDir dir;
    ui::MainWindow window;
    QString store = dir.filePath(QStringLiteral("lab.sqlite"));

    DataIoFixture() { EXPECT_TRUE(window.openStore(store, true, false)); }

    /// Imports `path` through the window's import flow; the id when stored.
    std::optional<qint64> import(const QString& path) {
        QSignalSpy finished(window.importFlow(), &ui::CampaignImportFlow::finished);
        QString why;
        EXPECT_TRUE(window.importFlow()->start(path, &why)) << why.toStdString();
        EXPECT_TRUE(test::waitFor(finished));
        if (finished.isEmpty()) return std::nullopt;
        return finished.first().first().value<std::optional<qint64>>();
    }
};

/// The store's campaigns as "id name runs samples", read-only.
QStringList campaignsOf(const QString& path) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    QStringList out;
    if (store)
        for (const db::CampaignSummary& c : store->listCampaigns())
            out << QStringLiteral("%1 %2 %3 %4").arg(c.id).arg(c.name).arg(c.runs).arg(c.samples);
    return out;
}

Campaign loadStored(const QString& path, qint64 id) {
    QString error;
    auto store = db::CampaignStore::open(path, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    auto campaign = store ? store->loadCampaign(id, &error) : std::nullopt;
    EXPECT_TRUE(campaign) << error.toStdString();
    return campaign.value_or(Campaign{});
}

QByteArray sha256Of(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

/// The example bundle copied to `dir` (to be spoiled or zipped).
QString copyExample(const QString& dir) {
    QDir().mkpath(dir);
    for (const QString& name : QDir(kExample).entryList(QDir::Files))
        EXPECT_TRUE(QFile::copy(QDir(kExample).filePath(name), QDir(dir).filePath(name)));
    return dir;
}

/// The example with line 3, column 3 of samples.csv spoiled (a temperature
/// that is not a number).
QString spoiledExample(const QString& dir) {
    copyExample(dir);
    QFile samples(QDir(dir).filePath(QStringLiteral("samples.csv")));
    EXPECT_TRUE(samples.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = samples.readAll().split('\n');
    samples.close();
    QList<QByteArray> cells = lines[2].split(',');
    cells[2] = "warm";
    lines[2] = cells.join(',');
    EXPECT_TRUE(samples.open(QIODevice::WriteOnly | QIODevice::Truncate));
    samples.write(lines.join('\n'));
    return dir;
}

TEST(DataIo, problemsAreSplitIntoFileLineColumnAndMessage) {
    const auto full = ui::parseImportProblem(QStringLiteral("error"),
                                             QStringLiteral("b/samples.csv:12:4: not a number"));
    EXPECT_EQ(full.file, QStringLiteral("b/samples.csv"));
    EXPECT_EQ(full.line, 12);
    EXPECT_EQ(full.column, 4);
    EXPECT_EQ(full.message, QStringLiteral("not a number"));
    const auto lineOnly = ui::parseImportProblem(
        QStringLiteral("warning"), QStringLiteral("campaign.json:7: unknown key 'x'"));
    EXPECT_EQ(lineOnly.line, 7);
    EXPECT_EQ(lineOnly.column, 0);
    EXPECT_EQ(lineOnly.message, QStringLiteral("unknown key 'x'"));
    const auto nowhere =
        ui::parseImportProblem(QStringLiteral("error"), QStringLiteral("import cancelled"));
    EXPECT_TRUE(nowhere.file.isEmpty());
    EXPECT_EQ(nowhere.message, QStringLiteral("import cancelled"));
}

TEST(DataIo, importsTheExampleFolderAndSelectsItsCampaign) {
    DataIoFixture f;
    const auto id = f.import(kExample);
    ASSERT_TRUE(id);
    EXPECT_EQ(f.window.session().campaignId(), id);
    const Campaign stored = loadStored(f.store, *id);
    EXPECT_FALSE(stored.runs.empty());
    EXPECT_FALSE(stored.runs.front().positioning.empty());
    EXPECT_EQ(campaignsOf(f.store).size(), 1);
    // The same content again is refused: the store keeps one campaign.
    EXPECT_FALSE(f.import(kExample));
    EXPECT_EQ(campaignsOf(f.store).size(), 1);
    EXPECT_TRUE(f.window.importFlow()->problemsDialog()->isVisible());
}

TEST(DataIo, importsAZipAsFileManagersWriteThem) {
    DataIoFixture f;
    copyExample(f.dir.filePath(QStringLiteral("bundle")));
    test::runTool(QStringLiteral("zip"),
                  {QStringLiteral("-qr"), QStringLiteral("bundle.zip"), QStringLiteral("bundle")},
                  f.dir.path());
    const auto id = f.import(f.dir.filePath(QStringLiteral("bundle.zip")));
    ASSERT_TRUE(id);
    const auto fromFolder = [&] {
        DataIoFixture g;
        const auto other = g.import(kExample);
        EXPECT_TRUE(other);
        return loadStored(g.store, other.value_or(0));
    }();
    EXPECT_TRUE(loadStored(f.store, *id) == fromFolder);
}

TEST(DataIo, aBadBundleListsItsErrorsAndLeavesTheStoreAsItWas) {
    DataIoFixture f;
    ASSERT_TRUE(f.import(kExample));
    const QStringList before = campaignsOf(f.store);
    const QByteArray hash = sha256Of(f.store);
    const QString bad = spoiledExample(f.dir.filePath(QStringLiteral("bad")));
    EXPECT_FALSE(f.import(bad));
    ui::ImportProblemsDialog* dialog = f.window.importFlow()->problemsDialog();
    ASSERT_TRUE(dialog->isVisible());
    const ui::ImportProblemsModel* model = dialog->model();
    ASSERT_GE(model->rowCount(), 1);
    const ui::ImportProblem& first = model->problem(0);
    EXPECT_EQ(first.level, QStringLiteral("error"));
    EXPECT_EQ(first.file, QStringLiteral("samples.csv"));  // relative to the bundle
    EXPECT_EQ(first.line, 3);
    EXPECT_EQ(first.column, 3);
    EXPECT_TRUE(first.message.contains(QStringLiteral("warm"))) << first.message.toStdString();
    EXPECT_TRUE(dialog->summary().contains(QStringLiteral("nothing was stored")));
    EXPECT_EQ(campaignsOf(f.store), before);
    EXPECT_EQ(sha256Of(f.store), hash);
}

TEST(DataIo, anExportedCampaignImportsAgainEqual) {
    DataIoFixture f;
    const auto id = f.import(kExample);
    ASSERT_TRUE(id);
    QAction* action = f.window.findChild<QAction*>(QStringLiteral("ExportCampaignAction"));
    ASSERT_TRUE(action);
    EXPECT_TRUE(action->isEnabled());
    const QString out = f.dir.filePath(QStringLiteral("exported"));
    QSignalSpy written(f.window.exportFlow(), &ui::CampaignExportFlow::finished);
    ASSERT_TRUE(f.window.exportFlow()->start(out));
    ASSERT_TRUE(test::waitFor(written));
    ASSERT_TRUE(written.first().first().toBool()) << written.first().at(1).toString().toStdString();
    EXPECT_TRUE(QFile::exists(QDir(out).filePath(QStringLiteral("samples.csv"))));
    // A second export to the same folder is refused and leaves it as it was.
    const QByteArray samplesHash = sha256Of(QDir(out).filePath(QStringLiteral("samples.csv")));
    ASSERT_TRUE(f.window.exportFlow()->start(out));
    ASSERT_TRUE(test::waitFor(written, 2));
    EXPECT_FALSE(written.at(1).first().toBool());
    EXPECT_EQ(sha256Of(QDir(out).filePath(QStringLiteral("samples.csv"))), samplesHash);

    DataIoFixture g;
    const auto again = g.import(out);
    ASSERT_TRUE(again);
    const Campaign original = loadStored(f.store, *id);
    const Campaign reimported = loadStored(g.store, *again);
    EXPECT_EQ(reimported.name, original.name);
    EXPECT_EQ(reimported.machine, original.machine);
    EXPECT_EQ(reimported.channels, original.channels);
    ASSERT_EQ(reimported.runs.size(), original.runs.size());
    for (std::size_t r = 0; r < original.runs.size(); ++r)
        EXPECT_TRUE(reimported.runs[r] == original.runs[r]) << "run " << r;
    EXPECT_TRUE(reimported == original);
}

TEST(DataIo, aBundleDroppedOnTheWindowIsImported) {
    DataIoFixture f;
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(kExample)});
    QSignalSpy finished(f.window.importFlow(), &ui::CampaignImportFlow::finished);
    QDragEnterEvent enter({10, 10}, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&f.window, &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&f.window, &drop);
    ASSERT_TRUE(test::waitFor(finished));
    const auto id = finished.first().first().value<std::optional<qint64>>();
    ASSERT_TRUE(id);
    EXPECT_EQ(campaignsOf(f.store).size(), 1);
    // A file that is not a bundle is not taken.
    QMimeData text;
    text.setUrls({QUrl::fromLocalFile(f.store)});
    QDragEnterEvent refused({10, 10}, Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    refused.setAccepted(false);
    QCoreApplication::sendEvent(&f.window, &refused);
    EXPECT_FALSE(refused.isAccepted());
}

const std::vector<double> kLaserTargets{50, 150, 250, 350, 450};

/// `text` (by default a vendor export of two cycles) as `dir`/laser-export.csv; its path.
QString writeLaserExport(DataIoFixture& f, const QByteArray& text = test::vendorCsv(
                                               test::vendorReadings(kLaserTargets, 2))) {
    const QString csv = f.dir.filePath(QStringLiteral("laser-export.csv"));
    QFile file(csv);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text);
    return csv;
}

/// `text` written to `dir`/laser-export.csv, dropped on the window, mapped
/// in its dialog (the preselection kept) and imported; the id when stored.
std::optional<qint64> importVendorCsv(DataIoFixture& f, const QByteArray& text) {
    const QString csv = writeLaserExport(f, text);
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(csv)});
    QDragEnterEvent enter({10, 10}, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&f.window, &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&f.window, &drop);
    ui::InterferometerCsvDialog* dialog = f.window.interferometerCsvDialog();
    EXPECT_TRUE(dialog->isVisible());
    dialog->machine->setText(QStringLiteral("VMC 1"));
    dialog->screw->length_mm->setValue(600);
    dialog->screw->diameter_mm->setValue(32);
    dialog->screw->lead_mm->setValue(10);
    dialog->screw->fixedEnd_mm->setValue(0);
    dialog->screw->nutLength_mm->setValue(80);
    EXPECT_EQ(dialog->validate(), QStringList{});
    QSignalSpy finished(f.window.importFlow(), &ui::CampaignImportFlow::finished);
    dialog->accept();
    EXPECT_FALSE(dialog->isVisible());
    EXPECT_TRUE(test::waitFor(finished));
    if (finished.isEmpty()) return std::nullopt;
    return finished.first().first().value<std::optional<qint64>>();
}

TEST(DataIo, anInterferometerCsvIsMappedInItsDialogAndStoredAsAPositioningRun) {
    DataIoFixture f;
    ui::InterferometerCsvDialog* dialog = f.window.interferometerCsvDialog();
    dialog->load(writeLaserExport(f));
    // The preview as the import reads the file; the vendor's names preselected.
    EXPECT_EQ(dialog->previewError(), QString());
    EXPECT_EQ(dialog->preview()->rowCount(), ui::InterferometerCsvDialog::kPreviewRows);
    EXPECT_EQ(dialog->preview()->columnCount(), 4);
    EXPECT_EQ(dialog->preview()->horizontalHeaderItem(2)->text(), QStringLiteral("Error [µm]"));
    using interferometer::ReadingRole;
    EXPECT_EQ(dialog->columnBox(ReadingRole::Time)->currentText(), QStringLiteral("Time [s]"));
    EXPECT_EQ(dialog->columnBox(ReadingRole::Position)->currentText(),
              QStringLiteral("Position (mm)"));
    EXPECT_EQ(dialog->columnBox(ReadingRole::Deviation)->currentText(),
              QStringLiteral("Error [µm]"));
    EXPECT_EQ(dialog->columnBox(ReadingRole::Air)->currentIndex(), 0);  // none
    EXPECT_TRUE(dialog->compensated->isChecked());

    const auto id = importVendorCsv(f, test::vendorCsv(test::vendorReadings(kLaserTargets, 2)));
    ASSERT_TRUE(id);
    EXPECT_EQ(campaignsOf(f.store).size(), 1);
    const Campaign stored = loadStored(f.store, *id);
    EXPECT_EQ(stored.name, QStringLiteral("laser-export"));
    EXPECT_EQ(stored.machine.name, QStringLiteral("VMC 1"));
    ASSERT_EQ(stored.runs.size(), 1u);
    const driftlab::Run& run = stored.runs.front();
    EXPECT_EQ(run.kind, RunKind::Positioning);
    ASSERT_EQ(run.positioning.size(), 20u);
    std::set<double> targets;
    int negative = 0;
    for (const PositioningMeasurement& m : run.positioning) {
        targets.insert(m.target_mm);
        negative += m.direction == Direction::Negative;
    }
    EXPECT_EQ(targets, std::set<double>(kLaserTargets.begin(), kLaserTargets.end()));
    EXPECT_EQ(negative, 10);
    EXPECT_EQ(run.positioning.back().cycle, 2);
}

TEST(DataIo, aBadInterferometerCsvListsItsLineAndColumnAndStoresNothing) {
    DataIoFixture f;
    ASSERT_TRUE(f.import(kExample));
    const QStringList before = campaignsOf(f.store);
    const QByteArray hash = sha256Of(f.store);
    // Line 6 of the export: the error column (3) holds no number.
    QList<QByteArray> lines = test::vendorCsv(test::vendorReadings(kLaserTargets, 2)).split('\n');
    QList<QByteArray> cells = lines[5].split(';');
    cells[2] = "n/a";
    lines[5] = cells.join(';');
    EXPECT_FALSE(importVendorCsv(f, lines.join('\n')));
    ui::ImportProblemsDialog* problems = f.window.importFlow()->problemsDialog();
    ASSERT_TRUE(problems->isVisible());
    ASSERT_GE(problems->model()->rowCount(), 1);
    const ui::ImportProblem& first = problems->model()->problem(0);
    EXPECT_EQ(first.level, QStringLiteral("error"));
    EXPECT_EQ(first.file, QStringLiteral("laser-export.csv"));
    EXPECT_EQ(first.line, 6);
    EXPECT_EQ(first.column, 3);
    EXPECT_TRUE(first.message.contains(QStringLiteral("n/a"))) << first.message.toStdString();
    EXPECT_EQ(campaignsOf(f.store), before);
    EXPECT_EQ(sha256Of(f.store), hash);
}

// The import dialog's error list and the CSV mapping, for docs/gui-data.md: run
// under a real X server with DRIFTLAB_SCREENSHOT_DIR set,
//   DRIFTLAB_SCREENSHOT_DIR=docs/images xvfb-run -a -s "-screen 0 1280x800x24"
//     build/tests/ui/ui_dataio_tests --gtest_filter='Screenshots.*'
TEST(Screenshots, importErrors) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "set DRIFTLAB_SCREENSHOT_DIR to take the screenshot";
    DataIoFixture f;
    f.window.resize(1280, 800);
    f.window.move(0, 0);
    f.window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&f.window));
    ASSERT_TRUE(f.import(kExample));
    EXPECT_FALSE(f.import(spoiledExample(f.dir.filePath(QStringLiteral("x-axis-moving-state")))));
    ui::ImportProblemsDialog* dialog = f.window.importFlow()->problemsDialog();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    EXPECT_TRUE(dialog->grab().save(out + QStringLiteral("/gui-import.png")));
}

TEST(Screenshots, interferometerCsvMapping) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "set DRIFTLAB_SCREENSHOT_DIR to take the screenshot";
    DataIoFixture f;
    ui::InterferometerCsvDialog* dialog = f.window.interferometerCsvDialog();
    dialog->load(writeLaserExport(f));
    dialog->machine->setText(QStringLiteral("VMC 1"));
    dialog->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    EXPECT_TRUE(dialog->grab().save(out + QStringLiteral("/gui-import-csv.png")));
}
