#pragma once
// Set-up sections "Machine" and "Travel and interferometer": the campaign and
// machine names, the axis travel, the interferometer's dead path and whether
// it compensates for the air itself. The targets it reads at come from the
// procedure (shown in the Procedure section).

#include <QWidget>

#include "core/domain/Campaign.h"
#include "ui/widgets/FieldErrors.h"

class QCheckBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;

namespace driftlab::ui {

class MachineForm : public QWidget {
    Q_OBJECT
public:
    explicit MachineForm(QWidget* parent = nullptr);

    void setCampaign(const Campaign& campaign);
    /// Writes the fields into `campaign`, keeping what the form does not show.
    void applyTo(Campaign& campaign) const;
    /// Marks bad fields and appends "Machine → name: …" lines to `summary`.
    void validate(QStringList& summary);
    const FieldErrors& errors() const { return m_errors; }

    QLineEdit* campaignName;
    QLineEdit* machineName;
    QLineEdit* axis;
    QLineEdit* controller;
    QGroupBox* travel;
    QDoubleSpinBox* travelFrom_mm;
    QDoubleSpinBox* travelTo_mm;
    QGroupBox* interferometer;
    QDoubleSpinBox* deadPath_mm;
    QCheckBox* environmentCompensation;
    QLabel* targets;  ///< the procedure's targets, shown for reference

private:
    FieldErrors m_errors;
};

/// A spin box for a length or coefficient: wide range, `decimals`, a suffix.
QDoubleSpinBox* numberBox(int decimals, const QString& suffix, QWidget* parent);

}  // namespace driftlab::ui
