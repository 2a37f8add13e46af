#include "ui/widgets/ScrewForm.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QVBoxLayout>

#include "ui/widgets/MachineForm.h"

namespace driftlab::ui {
namespace {
const QStringList kMountings{QStringLiteral("fixed-free"), QStringLiteral("fixed-supported"),
                             QStringLiteral("fixed-fixed")};
}  // namespace

ScrewForm::ScrewForm(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    screw = new QGroupBox(tr("Ball screw (needed for feed-axis runs)"), this);
    screw->setCheckable(true);
    auto* columns = new QHBoxLayout(screw);
    auto* geometry = new QFormLayout;
    auto* material = new QFormLayout;
    columns->addLayout(geometry, 1);
    columns->addLayout(material, 1);

    length_mm = numberBox(1, tr("mm"), screw);
    diameter_mm = numberBox(2, tr("mm"), screw);
    lead_mm = numberBox(3, tr("mm"), screw);
    fixedEnd_mm = numberBox(1, tr("mm"), screw);
    mounting = new QComboBox(screw);
    mounting->addItems(kMountings);
    nutLength_mm = numberBox(1, tr("mm"), screw);
    nutLength_mm->setSpecialValueText(tr("not given"));
    nutLength_mm->setMinimum(0);
    m_errors.addRow(geometry, tr("Length (mm)"), length_mm);
    m_errors.addRow(geometry, tr("Diameter (mm)"), diameter_mm);
    m_errors.addRow(geometry, tr("Lead (mm)"), lead_mm);
    m_errors.addRow(geometry, tr("Fixed end at (mm, axis)"), fixedEnd_mm);
    m_errors.addRow(geometry, tr("Mounting"), mounting);
    m_errors.addRow(geometry, tr("Nut length (mm)"), nutLength_mm);

    alpha_um_per_mK = numberBox(2, tr("µm/(m·K)"), screw);
    density_kg_m3 = numberBox(0, tr("kg/m³"), screw);
    specificHeat_J_kgK = numberBox(0, tr("J/(kg·K)"), screw);
    conductivity_W_mK = numberBox(1, tr("W/(m·K)"), screw);
    m_errors.addRow(material, tr("Expansion α (µm/(m·K))"), alpha_um_per_mK);
    m_errors.addRow(material, tr("Density ρ (kg/m³)"), density_kg_m3);
    m_errors.addRow(material, tr("Specific heat c (J/(kg·K))"), specificHeat_J_kgK);
    m_errors.addRow(material, tr("Conductivity k (W/(m·K))"), conductivity_W_mK);
    layout->addWidget(screw);
    layout->addStretch(1);
}

void ScrewForm::setCampaign(const Campaign& c) {
    screw->setChecked(c.screw.has_value());
    const Screw s = c.screw.value_or(Screw{});
    length_mm->setValue(s.length_mm);
    diameter_mm->setValue(s.diameter_mm);
    lead_mm->setValue(s.lead_mm);
    fixedEnd_mm->setValue(s.fixed_end_mm);
    const int m = mounting->findText(s.mounting);
    mounting->setCurrentIndex(m >= 0 ? m : 1);
    alpha_um_per_mK->setValue(s.alpha_per_K * 1e6);
    density_kg_m3->setValue(s.density_kg_m3);
    specificHeat_J_kgK->setValue(s.specific_heat_J_kgK);
    conductivity_W_mK->setValue(s.conductivity_W_mK);
    nutLength_mm->setValue(c.nut_length_mm.value_or(0));
}

void ScrewForm::applyTo(Campaign& c) const {
    c.nut_length_mm.reset();
    if (nutLength_mm->value() > 0) c.nut_length_mm = nutLength_mm->value();
    if (!screw->isChecked()) {
        c.screw.reset();
        return;
    }
    Screw s = c.screw.value_or(Screw{});  // keeps the keys this form does not show
    s.length_mm = length_mm->value();
    s.diameter_mm = diameter_mm->value();
    s.lead_mm = lead_mm->value();
    s.fixed_end_mm = fixedEnd_mm->value();
    s.mounting = mounting->currentText();
    s.alpha_per_K = alpha_um_per_mK->value() * 1e-6;
    s.density_kg_m3 = density_kg_m3->value();
    s.specific_heat_J_kgK = specificHeat_J_kgK->value();
    s.conductivity_W_mK = conductivity_W_mK->value();
    c.screw = s;
}

void ScrewForm::validate(QStringList& summary) {
    m_errors.clear();
    if (!screw->isChecked()) return;
    const struct {
        QDoubleSpinBox* box;
        const char* name;
        const char* unit;
    } positives[] = {
        {length_mm, "length", "mm"},
        {diameter_mm, "diameter", "mm"},
        {lead_mm, "lead", "mm"},
        {alpha_um_per_mK, "α", "µm/(m·K)"},
        {density_kg_m3, "ρ", "kg/m³"},
        {specificHeat_J_kgK, "c", "J/(kg·K)"},
        {conductivity_W_mK, "k", "W/(m·K)"},
    };
    for (const auto& p : positives)
        if (p.box->value() <= 0)
            m_errors.fail(p.box, tr("Screw → %1").arg(QString::fromUtf8(p.name)),
                          tr("must be > 0 %1").arg(QString::fromUtf8(p.unit)), summary);
    if (diameter_mm->value() > 0 && length_mm->value() > 0 &&
        diameter_mm->value() >= length_mm->value())
        m_errors.fail(diameter_mm, tr("Screw → diameter"),
                      tr("must be smaller than the length (%1 mm)").arg(length_mm->value()),
                      summary);
}

}  // namespace driftlab::ui
