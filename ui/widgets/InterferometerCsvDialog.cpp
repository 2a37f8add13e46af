#include "ui/widgets/InterferometerCsvDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>
#include <memory>
#include <utility>

#include "core/bundle/CsvTable.h"
#include "core/interferometer/AirRefractiveIndex.h"
#include "ui/widgets/ScrewForm.h"

namespace driftlab::ui {

using interferometer::ReadingRole;

InterferometerCsvDialog::InterferometerCsvDialog(QWidget* parent)
    : QDialog(parent),
      compensated(new QCheckBox(tr("The interferometer compensated itself for the air"), this)),
      assumedIndex(new QDoubleSpinBox(this)),
      wavelength_nm(new QDoubleSpinBox(this)),
      campaignName(new QLineEdit(this)),
      machine(new QLineEdit(this)),
      axis(new QLineEdit(QStringLiteral("X"), this)),
      runId(new QLineEdit(QStringLiteral("P1"), this)),
      targets(new QLineEdit(this)),
      tolerance_mm(new QDoubleSpinBox(this)),
      screw(new ScrewForm(this)),
      m_preview(new QStandardItemModel(this)),
      m_view(new QTableView(this)),
      m_status(new QLabel(this)) {
    setObjectName(QStringLiteral("InterferometerCsvDialog"));
    setWindowTitle(tr("Import interferometer CSV export"));
    m_view->setModel(m_preview);
    m_view->setObjectName(QStringLiteral("InterferometerCsvPreview"));
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_status->setWordWrap(true);

    auto* columns = new QGroupBox(tr("Columns"), this);
    auto* columnForm = new QFormLayout(columns);
    for (ReadingRole role : interferometer::kReadingRoles) {
        auto* box = new QComboBox(columns);
        box->setObjectName(interferometer::layoutColumn(role));
        m_columns[std::size_t(role)] = box;
        columnForm->addRow(interferometer::roleLabel(role), box);
    }
    compensated->setChecked(true);
    assumedIndex->setDecimals(9);
    assumedIndex->setRange(0.9, 1.1);
    assumedIndex->setValue(1.0);
    wavelength_nm->setDecimals(6);
    wavelength_nm->setRange(100, 2000);
    wavelength_nm->setValue(interferometer::kHeNeVacuumWavelength_nm);
    columnForm->addRow(compensated);
    columnForm->addRow(tr("n0 it converted with"), assumedIndex);
    columnForm->addRow(tr("Vacuum wavelength (nm)"), wavelength_nm);
    const auto compensation = [this](bool on) {
        assumedIndex->setEnabled(!on);
        wavelength_nm->setEnabled(!on);
    };
    connect(compensated, &QCheckBox::toggled, this, compensation);
    compensation(true);

    auto* run = new QGroupBox(tr("Campaign and run"), this);
    auto* runForm = new QFormLayout(run);
    targets->setPlaceholderText(tr("inferred from the readings"));
    tolerance_mm->setRange(0.001, 100);
    tolerance_mm->setDecimals(3);
    tolerance_mm->setValue(0.5);
    runForm->addRow(tr("Campaign name"), campaignName);
    runForm->addRow(tr("Machine"), machine);
    runForm->addRow(tr("Axis"), axis);
    runForm->addRow(tr("Run id"), runId);
    runForm->addRow(tr("Targets (mm, comma-separated)"), targets);
    runForm->addRow(tr("Target tolerance (mm)"), tolerance_mm);
    // A positioning run is a feed-axis run: the format wants the screw.
    Campaign withScrew;
    withScrew.screw = Screw{};
    screw->setCampaign(withScrew);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &InterferometerCsvDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* fields = new QHBoxLayout;
    fields->addWidget(columns);
    fields->addWidget(run);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    layout->addLayout(fields);
    layout->addWidget(screw);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    resize(900, 760);
}

void InterferometerCsvDialog::load(const QString& path) {
    m_path = path;
    m_previewError.clear();
    m_preview->clear();
    std::vector<QString> header;
    // The bundle's CSV reader, as the import reads the file: ';' files with
    // decimal commas and quoted cells look here as they will be read.
    try {
        auto file = std::make_unique<QFile>(path);
        if (!file->open(QIODevice::ReadOnly))
            throw bundle::BundleException({QFileInfo(path).fileName(), 0, 0, file->errorString()});
        bundle::CsvTable table(std::move(file), QFileInfo(path).fileName());
        header = table.header();
        QStringList labels;
        for (const QString& h : header) labels << h;
        m_preview->setHorizontalHeaderLabels(labels);
        for (int row = 0; row < kPreviewRows && table.next(); ++row) {
            QList<QStandardItem*> items;
            for (std::size_t c = 0; c < header.size(); ++c)
                items << new QStandardItem(table.text(int(c)));
            m_preview->appendRow(items);
        }
    } catch (const bundle::BundleException& e) {
        m_previewError = e.error.toString();
    }
    for (ReadingRole role : interferometer::kReadingRoles) {
        QComboBox* box = columnBox(role);
        box->clear();
        box->addItem(interferometer::isRequired(role) ? tr("(choose a column)") : tr("none"));
        for (const QString& h : header) box->addItem(h, h);
        const auto guess = interferometer::guessColumn(role, header);
        box->setCurrentIndex(guess ? *guess + 1 : 0);
    }
    campaignName->setText(QFileInfo(path).completeBaseName());
    m_status->setText(m_previewError.isEmpty()
                          ? tr("%1: the first rows as the import reads them").arg(path)
                          : m_previewError);
}

QStringList InterferometerCsvDialog::validate() {
    QStringList problems;
    if (!m_previewError.isEmpty()) problems << m_previewError;
    for (ReadingRole role : interferometer::kReadingRoles)
        if (interferometer::isRequired(role) && columnBox(role)->currentIndex() <= 0)
            problems << tr("Columns → %1: choose the file's column")
                            .arg(interferometer::roleLabel(role));
    for (const auto& [field, name] :
         {std::pair{campaignName, tr("campaign name")}, std::pair{machine, tr("machine")},
          std::pair{axis, tr("axis")}, std::pair{runId, tr("run id")}})
        if (field->text().trimmed().isEmpty())
            problems << tr("Campaign and run → %1: must not be empty").arg(name);
    bool targetsOk = true;
    for (const QString& t : targets->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        (void)t.trimmed().toDouble(&ok);
        targetsOk = targetsOk && ok;
    }
    if (!targetsOk)
        problems << tr("Campaign and run → targets: numbers in mm, separated by commas");
    screw->validate(problems);
    if (!screw->screw->isChecked() || screw->nutLength_mm->value() <= 0)
        problems << tr("Screw → a positioning run needs the ball screw and the nut length");
    return problems;
}

InterferometerCsvRequest InterferometerCsvDialog::request() const {
    InterferometerCsvRequest r;
    r.path = m_path;
    r.header.compensationOn = compensated->isChecked();
    r.header.assumedIndex = assumedIndex->value();
    r.header.vacuumWavelength_nm = wavelength_nm->value();
    for (ReadingRole role : interferometer::kReadingRoles)
        r.mapping[role] = columnBox(role)->currentData().toString();  // "" for none
    r.context.fileName = QFileInfo(m_path).fileName();
    r.context.campaignName = campaignName->text().trimmed();
    r.context.machine = machine->text().trimmed();
    r.context.axis = axis->text().trimmed();
    r.context.runId = runId->text().trimmed();
    for (const QString& t : targets->text().split(QLatin1Char(','), Qt::SkipEmptyParts))
        r.context.targets_mm.push_back(t.trimmed().toDouble());
    r.context.targetTolerance_mm = tolerance_mm->value();
    Campaign c;
    screw->applyTo(c);
    r.context.screw = c.screw;
    r.context.nut_length_mm = c.nut_length_mm;
    r.context.environmentCompensation = compensated->isChecked();
    return r;
}

void InterferometerCsvDialog::accept() {
    const QStringList problems = validate();
    if (!problems.isEmpty()) {
        m_status->setText(problems.join(QLatin1Char('\n')));
        return;
    }
    QDialog::accept();
}

}  // namespace driftlab::ui
