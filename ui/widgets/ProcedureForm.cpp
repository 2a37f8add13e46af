#include "ui/widgets/ProcedureForm.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <stdexcept>

#include "core/procedures/ProcedurePlan.h"

// The resources live in the static ui library: make sure they are linked in.
static void initSetupResources() {
    Q_INIT_RESOURCE(setup_resources);
}

namespace driftlab::ui {

using procedures::Procedure;

QStringList ProcedureForm::shippedProcedures() {
    initSetupResources();
    QStringList paths;
    const QDir dir(QStringLiteral(":/procedures"));
    for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        paths << dir.filePath(name);
    return paths;
}

ProcedureForm::ProcedureForm(QWidget* parent)
    : QWidget(parent),
      source(new QComboBox(this)),
      json(new QPlainTextEdit(this)),
      m_keyForm(new QFormLayout),
      m_kind(new QLabel(this)),
      m_total(new QLabel(this)),
      m_errorLabel(new QLabel(this)),
      m_runs(new QTableWidget(0, 5, this)) {
    auto* layout = new QVBoxLayout(this);
    auto* pick = new QHBoxLayout;
    pick->addWidget(new QLabel(tr("Procedure:"), this));
    for (const QString& path : shippedProcedures())
        source->addItem(tr("%1 (shipped)").arg(QFileInfo(path).completeBaseName()), path);
    source->setCurrentIndex(-1);
    pick->addWidget(source, 1);
    auto* open = new QPushButton(tr("Open file…"), this);
    pick->addWidget(open);
    layout->addLayout(pick);

    auto* columns = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    auto* keyBox = new QGroupBox(tr("Key numbers"), this);
    keyBox->setLayout(m_keyForm);
    left->addWidget(keyBox);
    auto* runsBox = new QGroupBox(tr("Runs (planned)"), this);
    auto* runsLayout = new QVBoxLayout(runsBox);
    m_kind->setWordWrap(true);
    runsLayout->addWidget(m_kind);
    m_runs->setHorizontalHeaderLabels(
        {tr("Run"), tr("Kind"), tr("Feed (mm/min)"), tr("Range (mm)"), tr("Duration")});
    m_runs->verticalHeader()->hide();
    m_runs->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_runs->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_runs->horizontalHeader()->setStretchLastSection(true);
    runsLayout->addWidget(m_runs, 1);
    m_total->setWordWrap(true);
    runsLayout->addWidget(m_total);
    left->addWidget(runsBox, 1);
    columns->addLayout(left, 1);

    auto* jsonBox = new QGroupBox(tr("Procedure file (JSON, docs/procedures.md)"), this);
    auto* jsonLayout = new QVBoxLayout(jsonBox);
    json->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    json->setLineWrapMode(QPlainTextEdit::NoWrap);
    jsonLayout->addWidget(json, 1);
    columns->addWidget(jsonBox, 1);
    layout->addLayout(columns, 1);
    m_errorLabel->setStyleSheet(QStringLiteral("color: #c02020;"));
    m_errorLabel->setWordWrap(true);
    m_errorLabel->hide();
    layout->addWidget(m_errorLabel);

    connect(source, &QComboBox::activated, this, [this](int index) {
        QString error;
        if (!loadFile(source->itemData(index).toString(), &error)) emit loadFailed(error);
    });
    connect(open, &QPushButton::clicked, this, &ProcedureForm::openFile);
    connect(json, &QPlainTextEdit::textChanged, this, [this] {
        if (!m_writing) readJson();
    });
}

void ProcedureForm::openFile() {
    // Not modal for the application: a run may be going on.
    auto* dialog = new QFileDialog(this, tr("Open a procedure"), QFileInfo(m_path).path(),
                                   tr("Procedures (*.json)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        QString error;
        if (!loadFile(path, &error)) emit loadFailed(error);
    });
    dialog->open();
}

bool ProcedureForm::loadFile(const QString& path, QString* error) {
    initSetupResources();
    const auto procedure = procedures::loadProcedureFile(path, error);
    if (!procedure) {
        m_errorLabel->setText(*error);
        m_errorLabel->show();
        return false;
    }
    setProcedure(*procedure, path);
    return true;
}

void ProcedureForm::setProcedure(const Procedure& procedure, const QString& path) {
    m_path = path;
    int index = source->findData(path);
    if (index < 0) {
        source->addItem(QFileInfo(path).fileName(), path);
        index = source->count() - 1;
    }
    source->setCurrentIndex(index);
    m_lastGood = procedure;
    writeJson();
    readJson();
}

void ProcedureForm::writeJson() {
    m_writing = true;
    json->setPlainText(QString::fromUtf8(
        QJsonDocument(procedures::toJson(*m_lastGood)).toJson(QJsonDocument::Indented)));
    m_writing = false;
}

void ProcedureForm::readJson() {
    m_error.clear();
    m_procedure.reset();
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json->toPlainText().toUtf8(), &parseError);
    if (parseError.error != QJsonParseError::NoError)
        m_error = tr("not valid JSON at offset %1: %2")
                      .arg(parseError.offset)
                      .arg(parseError.errorString());
    else if (!doc.isObject())
        m_error = tr("the file must hold a JSON object");
    else if (auto parsed = procedures::parseProcedure(doc.object(), &m_error))
        m_procedure = std::move(parsed);
    if (m_procedure) {
        try {
            (void)procedures::planRuns(*m_procedure);
            m_lastGood = m_procedure;
        } catch (const std::exception& e) {
            m_error = QString::fromStdString(e.what());
            m_procedure.reset();
        }
    }
    m_errorLabel->setText(m_error.isEmpty() ? QString() : tr("Procedure: %1").arg(m_error));
    m_errorLabel->setVisible(!m_error.isEmpty());
    rebuildKeyNumbers();
    showSummary();
    emit procedureChanged();
}

void ProcedureForm::rebuildKeyNumbers() {
    if (!m_lastGood) return;
    if (m_keyKind != m_lastGood->kind) {
        while (m_keyForm->rowCount() > 0) m_keyForm->removeRow(0);
        keyBoxes.clear();
        m_keyNumbers = keyNumbersOf(m_lastGood->kind);
        m_keyKind = m_lastGood->kind;
        for (std::size_t i = 0; i < m_keyNumbers.size(); ++i) {
            auto* box = new QDoubleSpinBox(this);
            box->setRange(0, 1e7);
            box->setDecimals(m_keyNumbers[i].decimals);
            box->setToolTip(m_keyNumbers[i].key);
            box->setKeyboardTracking(false);
            m_keyForm->addRow(m_keyNumbers[i].label, box);
            keyBoxes.push_back(box);
            connect(box, &QDoubleSpinBox::valueChanged, this, [this, i](double value) {
                if (m_writing || !m_lastGood) return;
                m_keyNumbers[i].set(*m_lastGood, value);
                writeJson();
                readJson();
            });
        }
    }
    m_writing = true;
    for (std::size_t i = 0; i < keyBoxes.size(); ++i)
        keyBoxes[i]->setValue(m_keyNumbers[i].get(*m_lastGood));
    m_writing = false;
}

void ProcedureForm::showSummary() {
    m_runs->setRowCount(0);
    if (!m_procedure) {
        m_kind->setText(tr("The procedure does not read: see the message below."));
        m_total->clear();
        return;
    }
    const auto runs = procedures::planRuns(*m_procedure);
    m_kind->setText(tr("<b>%1</b> — kind %2, %3 run(s), a sample every %4 s")
                        .arg(m_procedure->name.toHtmlEscaped(), toString(m_procedure->kind))
                        .arg(runs.size())
                        .arg(m_procedure->sample_interval_s));
    double total_s = 0;
    for (const auto& run : runs) {
        const double duration_s = std::max(run.programme.duration_s, run.duration_s);
        total_s += duration_s;
        const int row = m_runs->rowCount();
        m_runs->insertRow(row);
        const QString range =
            run.range_mm
                ? QStringLiteral("%1 – %2").arg(run.range_mm->from_mm).arg(run.range_mm->to_mm)
                : QStringLiteral("—");
        const QString feed =
            run.feed_mm_min ? QString::number(*run.feed_mm_min) : QStringLiteral("—");
        const QStringList cells{run.id, toString(run.kind), feed, range,
                                readableDuration(duration_s)};
        for (int c = 0; c < cells.size(); ++c)
            m_runs->setItem(row, c, new QTableWidgetItem(cells[c]));
    }
    QString total = tr("Total %1").arg(readableDuration(total_s));
    if (m_speedup > 0)
        total += tr("; about %1 at speed-up %2 on the simulated rig")
                     .arg(readableDuration(total_s / m_speedup))
                     .arg(m_speedup);
    m_total->setText(total);
}

void ProcedureForm::setSpeedup(double speedup) {
    m_speedup = speedup;
    showSummary();
}

void ProcedureForm::validate(QStringList& summary) const {
    if (!m_procedure)
        summary << tr("Procedure → %1")
                       .arg(m_error.isEmpty() ? tr("none chosen: pick one or open a file")
                                              : m_error);
}

}  // namespace driftlab::ui
