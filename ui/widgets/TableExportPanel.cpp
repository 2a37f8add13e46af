#include "ui/widgets/TableExportPanel.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSpinBox>

#include "core/compensation/TableExport.h"

namespace driftlab::ui {
namespace {

/// The file name a controller expects, or a plain one.
QString suggestedName(const QString& format) {
    if (format.startsWith(QLatin1String("linuxcnc"))) return QStringLiteral("comp.txt");
    if (format == QLatin1String("fanuc")) return QStringLiteral("pitch.prm");
    if (format == QLatin1String("fanuc-g10")) return QStringLiteral("pitch-g10.nc");
    if (format == QLatin1String("sinumerik")) return QStringLiteral("eec.ini");
    if (format == QLatin1String("heidenhain")) return QStringLiteral("X.COM");
    return QStringLiteral("compensation.csv");
}

}  // namespace

TableExportPanel::TableExportPanel(QWidget* parent)
    : QWidget(parent),
      m_format(new QComboBox(this)),
      m_axis(new QLineEdit(this)),
      m_magnification(new QSpinBox(this)),
      m_path(new QLineEdit(this)),
      m_browse(new QPushButton(tr("Browse…"), this)),
      m_export(new QPushButton(tr("Export"), this)) {
    m_format->addItems(compensation::tableFormats());
    m_format->setToolTip(tr("The controller's file format (docs/compensation.md)"));
    m_axis->setPlaceholderText(tr("default"));
    m_axis->setToolTip(
        tr("Sinumerik axis name (AX1), Heidenhain axis key (the campaign's axis) "
           "or Fanuc axis number (1)"));
    m_axis->setMaximumWidth(80);
    m_magnification->setRange(1, 100);
    m_magnification->setToolTip(tr("Fanuc parameter 3623, the pitch error magnification"));
    m_path->setPlaceholderText(tr("file to write"));
    m_export->setEnabled(false);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(new QLabel(tr("Export as"), this));
    layout->addWidget(m_format);
    layout->addWidget(new QLabel(tr("axis"), this));
    layout->addWidget(m_axis);
    layout->addWidget(new QLabel(tr("Fanuc ×"), this));
    layout->addWidget(m_magnification);
    layout->addWidget(m_path, 1);
    layout->addWidget(m_browse);
    layout->addWidget(m_export);
    connect(m_browse, &QPushButton::clicked, this, &TableExportPanel::browse);
    connect(m_export, &QPushButton::clicked, this, &TableExportPanel::exportNow);
    connect(m_format, &QComboBox::currentTextChanged, this, [this](const QString& format) {
        // Follow the format with the file name, keeping the folder.
        if (m_path->text().isEmpty()) return;
        const QFileInfo info(m_path->text());
        m_path->setText(info.dir().filePath(suggestedName(format)));
    });
}

void TableExportPanel::setTable(const std::optional<compensation::CompensationTable>& table,
                                const QString& campaignAxis) {
    m_table = table;
    m_campaignAxis = campaignAxis;
    m_export->setEnabled(m_table.has_value());
}

void TableExportPanel::browse() {
    // Not exec(): a run may be going on; the dialog answers through a signal.
    auto* dialog = new QFileDialog(this, tr("Export the compensation table"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->selectFile(m_path->text().isEmpty() ? suggestedName(m_format->currentText())
                                                : m_path->text());
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        m_path->setText(path);
        exportNow();
    });
    dialog->open();
}

void TableExportPanel::exportNow() {
    const QString format = m_format->currentText();
    const QString path = m_path->text().trimmed();
    if (!m_table) return emit exportFailed(tr("Export: there is no table"));
    if (path.isEmpty()) return emit exportFailed(tr("Export: give the file to write"));
    compensation::TableExportSettings settings;
    settings.axis = m_axis->text().trimmed();
    settings.campaign_axis = m_campaignAxis;
    settings.magnification = m_magnification->value();
    const compensation::ExportResult result = compensation::exportTable(*m_table, format, settings);
    if (!result.ok()) return emit exportFailed(tr("Export %1: %2").arg(format, result.error));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(result.text) != result.text.size() ||
        !file.commit())
        return emit exportFailed(
            tr("Export %1: %2: cannot write: %3").arg(format, path, file.errorString()));
    emit exported(path, result.warnings);
}

}  // namespace driftlab::ui
