#pragma once
// File → Import campaign… for an interferometer software's CSV export: the
// file's first rows as a preview, a column per quantity (preselected from the
// header's names, the optional ones may be none), whether the interferometer
// compensated itself (else its n0 and wavelength), and the campaign the run
// goes into. OK hands a request to CampaignImportFlow; nothing is read here
// beyond the preview.

#include <QDialog>
#include <QStringList>
#include <array>

#include "core/interferometer/InterferometerColumns.h"
#include "ui/shell/CampaignImportFlow.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QStandardItemModel;
class QTableView;

namespace driftlab::ui {

class ScrewForm;

class InterferometerCsvDialog : public QDialog {
    Q_OBJECT
public:
    /// Rows of the preview: enough to recognise the columns.
    static constexpr int kPreviewRows = 20;

    explicit InterferometerCsvDialog(QWidget* parent = nullptr);

    /// Shows `path`'s header and first rows and preselects the columns.
    void load(const QString& path);
    /// What the fields say (valid after validate() is empty).
    InterferometerCsvRequest request() const;
    /// The fields' problems, as "Section → field: reason"; empty when OK.
    QStringList validate();

    QStandardItemModel* preview() const { return m_preview; }
    QComboBox* columnBox(interferometer::ReadingRole role) const {
        return m_columns[std::size_t(role)];
    }
    /// The preview's problem (a file that cannot be read as CSV), or empty.
    QString previewError() const { return m_previewError; }

    QCheckBox* compensated;
    QDoubleSpinBox* assumedIndex;
    QDoubleSpinBox* wavelength_nm;
    QLineEdit* campaignName;
    QLineEdit* machine;
    QLineEdit* axis;
    QLineEdit* runId;
    QLineEdit* targets;  ///< empty: inferred from the readings
    QDoubleSpinBox* tolerance_mm;
    ScrewForm* screw;

public slots:
    void accept() override;

private:
    QString m_path;
    QString m_previewError;
    QStandardItemModel* m_preview;
    QTableView* m_view;
    QLabel* m_status;
    std::array<QComboBox*, interferometer::kReadingRoles.size()> m_columns{};
};

}  // namespace driftlab::ui
