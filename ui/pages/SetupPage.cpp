#include "ui/pages/SetupPage.h"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <set>

#include "core/procedures/ProcedurePlan.h"
#include "ui/models/ChannelSetupModel.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ChannelTable.h"
#include "ui/widgets/MachineForm.h"
#include "ui/widgets/ProcedureForm.h"
#include "ui/widgets/RigForm.h"
#include "ui/widgets/ScrewForm.h"

namespace driftlab::ui {
namespace {

const QString kLastProcedureKey = QStringLiteral("setup/last_procedure");
const QString kDefaultProcedure = QStringLiteral(":/procedures/moving-states-s1-s5.json");

QWidget* scrolled(QWidget* form) {
    auto* area = new QScrollArea;
    area->setWidget(form);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    return area;
}

/// The section a problem line belongs to, by its prefix.
SetupPage::Section sectionOf(const QString& problem) {
    if (problem.startsWith(QStringLiteral("Screw"))) return SetupPage::ScrewSection;
    if (problem.startsWith(QStringLiteral("Channels"))) return SetupPage::ChannelsSection;
    if (problem.startsWith(QStringLiteral("Procedure"))) return SetupPage::ProcedureSection;
    if (problem.startsWith(QStringLiteral("Rig"))) return SetupPage::RigSection;
    return SetupPage::MachineSection;
}

const char* kSectionNames[] = {"Machine, travel,\ninterferometer", "Screw", "Channels", "Procedure",
                               "Rig"};

}  // namespace

SetupPage::SetupPage(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_banner(new QLabel(this)),
      m_sections(new QListWidget(this)),
      m_stack(new QStackedWidget(this)),
      m_machine(new MachineForm),
      m_screw(new ScrewForm),
      m_channels(new ChannelSetupModel(this)),
      m_channelTable(new ChannelTable(*m_channels)),
      m_procedure(new ProcedureForm),
      m_rig(new RigForm),
      m_problems(new QListWidget(this)),
      m_status(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    m_banner->setObjectName(QStringLiteral("DemoBanner"));
    m_banner->setWordWrap(true);
    m_banner->setStyleSheet(QStringLiteral(
        "background: #fff4c2; border: 1px solid #d9b600; padding: 6px; color: #3a3000;"));
    m_banner->hide();
    layout->addWidget(m_banner);

    auto* middle = new QHBoxLayout;
    for (const char* name : kSectionNames) m_sections->addItem(tr(name));
    m_sections->setFixedWidth(m_sections->sizeHintForColumn(0) + 24);
    m_sections->setObjectName(QStringLiteral("SetupSections"));
    middle->addWidget(m_sections);
    m_stack->addWidget(scrolled(m_machine));
    m_stack->addWidget(scrolled(m_screw));
    m_stack->addWidget(m_channelTable);
    m_stack->addWidget(m_procedure);
    m_stack->addWidget(scrolled(m_rig));
    middle->addWidget(m_stack, 1);
    layout->addLayout(middle, 1);
    connect(m_sections, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    m_sections->setCurrentRow(0);

    m_problems->setObjectName(QStringLiteral("SetupProblems"));
    m_problems->setMaximumHeight(90);
    m_problems->setStyleSheet(QStringLiteral("color: #c02020;"));
    m_problems->hide();
    connect(m_problems, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { m_sections->setCurrentRow(sectionOf(item->text())); });
    layout->addWidget(m_problems);
    buildButtons(layout);

    connect(m_rig, &RigForm::rigChanged, this, [this] {
        m_channels->setDeviceMap(m_rig->deviceMap());
        if (!m_rig->isSimulated()) m_banner->hide();
    });
    connect(m_rig, &RigForm::speedupChanged, m_procedure, &ProcedureForm::setSpeedup);
    connect(m_procedure, &ProcedureForm::procedureChanged, this, &SetupPage::showTargets);
    connect(m_procedure, &ProcedureForm::loadFailed, this, [this](const QString& error) {
        emit m_session.event(QStringLiteral("error"), QStringLiteral("set-up"), error);
    });

    m_rig->loadSettings();
    QString error;
    const QString last = QSettings().value(kLastProcedureKey, kDefaultProcedure).toString();
    if (!m_procedure->loadFile(last, &error)) m_procedure->loadFile(kDefaultProcedure, &error);
}

void SetupPage::buildButtons(QVBoxLayout* layout) {
    auto* row = new QHBoxLayout;
    auto* load = new QPushButton(tr("Load machine…"), this);
    auto* save = new QPushButton(tr("Save machine…"), this);
    load->setToolTip(
        tr("Read machine, screw, travel, interferometer and channels from a "
           "campaign.json"));
    save->setToolTip(
        tr("Write them as a campaign.json without runs (driftlab-cli run "
           "--machine FILE)"));
    auto* apply = new QPushButton(tr("Apply"), this);
    apply->setObjectName(QStringLiteral("ApplySetup"));
    apply->setDefault(true);
    m_status->setWordWrap(true);
    row->addWidget(load);
    row->addWidget(save);
    row->addWidget(m_status, 1);
    row->addWidget(apply);
    layout->addLayout(row);
    connect(load, &QPushButton::clicked, this, [this] { askMachineFile(false); });
    connect(save, &QPushButton::clicked, this, [this] { askMachineFile(true); });
    connect(apply, &QPushButton::clicked, this, &SetupPage::apply);
}

void SetupPage::askMachineFile(bool save) {
    // Not modal for the application: a run may be going on.
    auto* dialog =
        new QFileDialog(this, save ? tr("Save the machine set-up") : tr("Load a machine set-up"),
                        {}, tr("Campaign files (*.json)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(save ? QFileDialog::AcceptSave : QFileDialog::AcceptOpen);
    dialog->setFileMode(save ? QFileDialog::AnyFile : QFileDialog::ExistingFile);
    if (save) dialog->selectFile(QStringLiteral("campaign.json"));
    connect(dialog, &QFileDialog::fileSelected, this, [this, save](const QString& path) {
        QString error;
        const bool ok = save ? saveMachine(path, &error) : loadMachine(path, &error);
        if (!ok) {
            m_status->setText(error);
            emit m_session.event(QStringLiteral("error"), QStringLiteral("set-up"), error);
        }
    });
    dialog->open();
}

Campaign SetupPage::machine() const {
    Campaign c = m_base;
    m_machine->applyTo(c);
    m_screw->applyTo(c);
    c.channels = m_channels->channels();
    c.sample_columns.clear();
    for (const auto& channel : c.channels) c.sample_columns.push_back(channel.id);
    c.runs.clear();
    return c;
}

void SetupPage::setMachine(const Campaign& campaign) {
    m_base = campaign;
    m_base.runs.clear();
    m_machine->setCampaign(m_base);
    m_screw->setCampaign(m_base);
    m_channels->setChannels(m_base.channels);
    showTargets();
}

void SetupPage::showTargets() {
    const auto& procedure = m_procedure->procedure();
    std::set<double> targets;
    if (procedure)
        for (const auto& run : procedures::planRuns(*procedure))
            for (const auto& m : run.programme.measurements) targets.insert(m.target_mm);
    QStringList shown;
    for (double t : targets) shown << QString::number(t, 'f', 1);
    if (shown.size() > 12)
        shown = shown.mid(0, 5) << QStringLiteral("…") << shown.mid(shown.size() - 5);
    m_machine->targets->setText(
        targets.empty()
            ? tr("none (the procedure takes no interferometer readings)")
            : tr("%1 targets: %2 mm").arg(targets.size()).arg(shown.join(QStringLiteral(", "))));
}

QStringList SetupPage::validate() {
    QStringList problems;
    m_machine->validate(problems);
    m_screw->validate(problems);
    const QStringList channelProblems = m_channels->problems(!m_rig->isSimulated());
    m_channelTable->showProblems(channelProblems);
    problems << channelProblems;
    m_procedure->validate(problems);
    const auto& procedure = m_procedure->procedure();
    if (procedure && m_machine->travel->isChecked()) {
        const RangeMm machineTravel{m_machine->travelFrom_mm->value(),
                                    m_machine->travelTo_mm->value()};
        if (procedure->travel_mm.from_mm < machineTravel.from_mm ||
            procedure->travel_mm.to_mm > machineTravel.to_mm)
            problems << tr("Procedure → travel_mm: [%1, %2] mm is outside the machine's travel "
                           "[%3, %4] mm")
                            .arg(procedure->travel_mm.from_mm)
                            .arg(procedure->travel_mm.to_mm)
                            .arg(machineTravel.from_mm)
                            .arg(machineTravel.to_mm);
    }
    m_rig->validate(problems);

    m_problems->clear();
    m_problems->addItems(problems);
    m_problems->setVisible(!problems.isEmpty());
    markSections(problems);
    return problems;
}

void SetupPage::markSections(const QStringList& problems) {
    std::set<int> bad;
    for (const QString& p : problems) bad.insert(sectionOf(p));
    for (int i = 0; i < m_sections->count(); ++i) {
        QListWidgetItem* item = m_sections->item(i);
        item->setText(tr(kSectionNames[i]) + (bad.count(i) ? QStringLiteral("  ⚠") : QString()));
        item->setForeground(bad.count(i) ? QColor(0xc0, 0x20, 0x20) : palette().text().color());
    }
}

std::optional<RunSetup> SetupPage::currentSetup(QStringList* problems) {
    const QStringList found = validate();
    if (problems) *problems = found;
    if (!found.isEmpty()) return std::nullopt;
    RunSetup setup;
    setup.procedure = *m_procedure->procedure();
    setup.procedure_path = m_procedure->path();
    m_rig->applyTo(setup);
    setup.machine = machine();
    return setup;
}

bool SetupPage::apply() {
    QStringList problems;
    const auto setup = currentSetup(&problems);
    if (!setup) {
        m_status->setText(
            tr("Not applied: %n problem(s), listed above.", nullptr, int(problems.size())));
        emit m_session.event(QStringLiteral("warning"), QStringLiteral("set-up"),
                             tr("set-up not applied: %1").arg(problems.front()));
        return false;
    }
    m_session.setRunSetup(*setup);
    m_rig->saveSettings();
    QSettings().setValue(kLastProcedureKey, setup->procedure_path);
    m_status->setText(
        tr("Applied: “%1” on the %2 rig. The Run page runs it.")
            .arg(setup->procedure.name, m_rig->isSimulated() ? tr("simulated") : tr("Modbus")));
    emit m_session.event(QStringLiteral("info"), QStringLiteral("set-up"),
                         tr("set-up applied: %1").arg(setup->procedure.name));
    return true;
}

}  // namespace driftlab::ui
