#include "ui/widgets/MachineForm.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace driftlab::ui {

QDoubleSpinBox* numberBox(int decimals, const QString& suffix, QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    // Wide on purpose: the validation, not the spin box, says what is wrong.
    box->setRange(-1e7, 1e7);
    box->setDecimals(decimals);
    box->setSuffix(suffix.isEmpty() ? suffix : QLatin1Char(' ') + suffix);
    box->setMinimumWidth(130);
    return box;
}

MachineForm::MachineForm(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);

    auto* machineBox = new QGroupBox(tr("Machine"), this);
    auto* machineForm = new QFormLayout(machineBox);
    campaignName = new QLineEdit(machineBox);
    machineName = new QLineEdit(machineBox);
    axis = new QLineEdit(machineBox);
    controller = new QLineEdit(machineBox);
    campaignName->setPlaceholderText(tr("e.g. X axis, spring 2025"));
    axis->setPlaceholderText(tr("e.g. X"));
    controller->setPlaceholderText(tr("e.g. Sinumerik 840D, LinuxCNC"));
    m_errors.addRow(machineForm, tr("Campaign name"), campaignName);
    m_errors.addRow(machineForm, tr("Machine name"), machineName);
    m_errors.addRow(machineForm, tr("Axis"), axis);
    m_errors.addRow(machineForm, tr("Controller"), controller);
    layout->addWidget(machineBox);

    travel = new QGroupBox(tr("Travel of the axis"), this);
    travel->setCheckable(true);
    auto* travelForm = new QFormLayout(travel);
    travelFrom_mm = numberBox(1, tr("mm"), travel);
    travelTo_mm = numberBox(1, tr("mm"), travel);
    m_errors.addRow(travelForm, tr("From (mm)"), travelFrom_mm);
    m_errors.addRow(travelForm, tr("To (mm)"), travelTo_mm);
    layout->addWidget(travel);

    interferometer = new QGroupBox(tr("Laser interferometer"), this);
    interferometer->setCheckable(true);
    auto* ifmForm = new QFormLayout(interferometer);
    deadPath_mm = numberBox(1, tr("mm"), interferometer);
    environmentCompensation =
        new QCheckBox(tr("the interferometer compensates for the air itself"), interferometer);
    m_errors.addRow(ifmForm, tr("Dead path (mm)"), deadPath_mm);
    ifmForm->addRow(tr("Environment compensation"), environmentCompensation);
    targets = new QLabel(tr("(no procedure)"), interferometer);
    targets->setWordWrap(true);
    ifmForm->addRow(tr("Targets (from the procedure)"), targets);
    layout->addWidget(interferometer);
    layout->addStretch(1);
}

void MachineForm::setCampaign(const Campaign& c) {
    campaignName->setText(c.name);
    machineName->setText(c.machine.name);
    axis->setText(c.machine.axis);
    controller->setText(c.machine.controller);
    travel->setChecked(c.travel_mm.has_value());
    const RangeMm range = c.travel_mm.value_or(RangeMm{0, 700});
    travelFrom_mm->setValue(range.from_mm);
    travelTo_mm->setValue(range.to_mm);
    interferometer->setChecked(c.interferometer.has_value());
    const Interferometer ifm = c.interferometer.value_or(Interferometer{});
    deadPath_mm->setValue(ifm.dead_path_mm);
    environmentCompensation->setChecked(ifm.environment_compensation);
}

void MachineForm::applyTo(Campaign& c) const {
    c.name = campaignName->text().trimmed();
    c.machine.name = machineName->text().trimmed();
    c.machine.axis = axis->text().trimmed();
    c.machine.controller = controller->text().trimmed();
    c.travel_mm.reset();
    if (travel->isChecked()) c.travel_mm = RangeMm{travelFrom_mm->value(), travelTo_mm->value()};
    if (!interferometer->isChecked()) {
        c.interferometer.reset();
    } else {
        Interferometer ifm = c.interferometer.value_or(Interferometer{});
        ifm.dead_path_mm = deadPath_mm->value();
        ifm.environment_compensation = environmentCompensation->isChecked();
        c.interferometer = ifm;
    }
}

void MachineForm::validate(QStringList& summary) {
    m_errors.clear();
    if (campaignName->text().trimmed().isEmpty())
        m_errors.fail(campaignName, tr("Machine → campaign name"), tr("must not be empty"),
                      summary);
    if (machineName->text().trimmed().isEmpty())
        m_errors.fail(machineName, tr("Machine → machine name"), tr("must not be empty"), summary);
    if (travel->isChecked() && travelTo_mm->value() <= travelFrom_mm->value())
        m_errors.fail(travelTo_mm, tr("Travel → to"),
                      tr("must be greater than from (%1 mm)").arg(travelFrom_mm->value()), summary);
    if (interferometer->isChecked() && deadPath_mm->value() < 0)
        m_errors.fail(deadPath_mm, tr("Interferometer → dead path"), tr("must be ≥ 0 mm"), summary);
}

}  // namespace driftlab::ui
