#pragma once
// Set-up section "Screw": the ball screw's geometry, mounting and material
// (needed for feed-axis runs; a spindle or ETVE campaign may go without).
// α is shown in µm/(m·K), as data sheets give it, and stored per kelvin.

#include <QWidget>

#include "core/domain/Campaign.h"
#include "ui/widgets/FieldErrors.h"

class QComboBox;
class QDoubleSpinBox;
class QGroupBox;

namespace driftlab::ui {

class ScrewForm : public QWidget {
    Q_OBJECT
public:
    explicit ScrewForm(QWidget* parent = nullptr);

    void setCampaign(const Campaign& campaign);
    /// Writes the screw (or none) and the nut length into `campaign`.
    void applyTo(Campaign& campaign) const;
    /// Marks bad fields and appends "Screw → lead: must be > 0 mm" lines.
    void validate(QStringList& summary);
    const FieldErrors& errors() const { return m_errors; }

    QGroupBox* screw;
    QDoubleSpinBox* length_mm;
    QDoubleSpinBox* diameter_mm;
    QDoubleSpinBox* lead_mm;
    QDoubleSpinBox* fixedEnd_mm;
    QComboBox* mounting;
    QDoubleSpinBox* alpha_um_per_mK;
    QDoubleSpinBox* density_kg_m3;
    QDoubleSpinBox* specificHeat_J_kgK;
    QDoubleSpinBox* conductivity_W_mK;
    QDoubleSpinBox* nutLength_mm;  ///< 0 = not given

private:
    FieldErrors m_errors;
};

}  // namespace driftlab::ui
