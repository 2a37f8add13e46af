// The Compensation page driven through its widgets on a store made with the
// real CLI: the table it shows is what `driftlab-cli compensate --format csv`
// writes for the same run and settings, and every export is byte for byte the
// CLI's file.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QTest>

#include "core/compensation/TableExport.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/CompensationTableModel.h"
#include "ui/pages/CompensationPage.h"
#include "ui/shell/Session.h"
#include "ui/widgets/TableExportPanel.h"

using namespace driftlab;
using namespace driftlab::test;
using TableModel = ui::CompensationTableModel;

namespace {

struct Fixture {
    QTemporaryDir dir;
    qint64 campaign = 0;
    QString db;
    ui::Session session;
    std::unique_ptr<ui::CompensationPage> page;

    Fixture() {
        db = importExample(dir, &campaign);
        QString error;
        EXPECT_TRUE(session.openStore(db, false, &error)) << qPrintable(error);
        page = std::make_unique<ui::CompensationPage>(session);
        QSignalSpy updated(page.get(), &ui::CompensationPage::tableUpdated);
        session.selectCampaign(campaign);
        EXPECT_TRUE(waitFor(updated));
    }

    /// What the CLI writes for the same run with `options`, as text.
    QByteArray cli(const QString& format, const QStringList& options) {
        const QString out = dir.filePath(QStringLiteral("cli-") + format);
        QFile::remove(out);
        const CliResult r =
            runCli(QStringList{QStringLiteral("compensate"), QStringLiteral("--db"), db,
                               QStringLiteral("--campaign"), QString::number(campaign),
                               QStringLiteral("--run"), QStringLiteral("S1"),
                               QStringLiteral("--format"), format, QStringLiteral("--out"), out}
                   << options);
        if (r.exitCode != 0) return {};
        QFile file(out);
        EXPECT_TRUE(file.open(QIODevice::ReadOnly));
        return file.readAll();
    }

    /// The page's table as CSV rows, from the text the view displays.
    QByteArray shownCsv() const {
        const TableModel* m = page->tableModel();
        const bool bidirectional = page->bidirectionalBox()->isChecked();
        QByteArray csv = bidirectional ? "position_mm,correction_um,correction_minus_um,"
                                         "uncertainty_um\n"
                                       : "position_mm,correction_um,uncertainty_um\n";
        for (int row = 0; row < m->rowCount(); ++row) {
            csv += m->data(m->index(row, TableModel::Position)).toString().toLatin1() + ',';
            csv += m->data(m->index(row, TableModel::CorrectionPlus)).toString().toLatin1();
            if (bidirectional)
                csv +=
                    ',' + m->data(m->index(row, TableModel::CorrectionMinus)).toString().toLatin1();
            csv += ',' + m->data(m->index(row, TableModel::Uncertainty)).toString().toLatin1();
            csv += '\n';
        }
        return csv;
    }

    void settle(const std::function<void()>& change) {
        QSignalSpy updated(page.get(), &ui::CompensationPage::tableUpdated);
        change();
        EXPECT_GE(updated.count(), 1);  // rebuilt synchronously from the loaded campaign
    }
};

}  // namespace

TEST(CompensationPage, showsTheTableTheCliWritesAsCsvForTheSameRun) {
    Fixture f;
    ASSERT_EQ(f.page->runBox()->currentText(), QStringLiteral("S1"));
    ASSERT_GT(f.page->tableModel()->rowCount(), 2) << qPrintable(f.page->messageLabel()->text());
    EXPECT_EQ(f.shownCsv(), f.cli(QStringLiteral("csv"), {}));

    f.settle([&] { QTest::mouseClick(f.page->spacingButton(), Qt::LeftButton); });
    f.settle([&] { f.page->spacingBox()->setValue(35); });
    EXPECT_EQ(f.page->tableModel()->rowCount(), 21);
    EXPECT_EQ(f.shownCsv(),
              f.cli(QStringLiteral("csv"), {QStringLiteral("--spacing"), QStringLiteral("35")}));

    f.settle([&] { QTest::mouseClick(f.page->pointsButton(), Qt::LeftButton); });
    f.settle([&] { f.page->pointsBox()->setValue(11); });
    f.settle([&] { f.page->bidirectionalBox()->setChecked(true); });
    EXPECT_EQ(f.page->tableModel()->rowCount(), 11);
    EXPECT_EQ(f.shownCsv(),
              f.cli(QStringLiteral("csv"), {QStringLiteral("--points"), QStringLiteral("11"),
                                            QStringLiteral("--bidirectional")}));
}

TEST(CompensationPage, aTableTheCoreRefusesIsNamedAndCannotBeExported) {
    Fixture f;
    // 0.001 mm over the travel: far more points than any controller takes.
    f.settle([&] { QTest::mouseClick(f.page->spacingButton(), Qt::LeftButton); });
    f.settle([&] { f.page->spacingBox()->setValue(0.001); });
    EXPECT_EQ(f.page->tableModel()->rowCount(), 0);
    EXPECT_TRUE(f.page->messageLabel()->text().contains(QStringLiteral("run S1")))
        << qPrintable(f.page->messageLabel()->text());
    EXPECT_FALSE(f.page->exportPanel()->exportButton()->isEnabled());
}

TEST(CompensationPage, exportWritesEveryFormatAsTheCliDoes) {
    Fixture f;
    f.settle([&] { QTest::mouseClick(f.page->spacingButton(), Qt::LeftButton); });
    f.settle([&] { f.page->spacingBox()->setValue(35); });
    ui::TableExportPanel* panel = f.page->exportPanel();
    int compared = 0;
    for (const QString& format : compensation::tableFormats()) {
        SCOPED_TRACE(format.toStdString());
        const QByteArray expected =
            f.cli(format, {QStringLiteral("--spacing"), QStringLiteral("35")});
        const QString path = f.dir.filePath(QStringLiteral("gui-") + format);
        panel->formatBox()->setCurrentText(format);
        panel->pathEdit()->setText(path);
        QSignalSpy written(panel, &ui::TableExportPanel::exported);
        QSignalSpy failed(panel, &ui::TableExportPanel::exportFailed);
        QTest::mouseClick(panel->exportButton(), Qt::LeftButton);
        if (expected.isEmpty()) {  // the CLI refuses this table for the format: so does the page
            EXPECT_EQ(failed.count(), 1);
            EXPECT_FALSE(QFile::exists(path));
            continue;
        }
        ASSERT_EQ(written.count(), 1) << qPrintable(f.page->messageLabel()->text());
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        EXPECT_EQ(file.readAll(), expected);
        ++compared;
    }
    EXPECT_GE(compared, 5);
}
