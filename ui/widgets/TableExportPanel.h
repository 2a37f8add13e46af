#pragma once
// Export of the Compensation page's table to a controller's file format,
// through the same core exporters as `driftlab-cli compensate --format`, so
// the files are byte for byte the CLI's; written atomically (QSaveFile).

#include <QWidget>
#include <optional>

#include "core/compensation/CompensationTable.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace driftlab::ui {

class TableExportPanel : public QWidget {
    Q_OBJECT
public:
    explicit TableExportPanel(QWidget* parent = nullptr);

    /// The table to export and the campaign's axis name (Heidenhain's default column).
    void setTable(const std::optional<compensation::CompensationTable>& table,
                  const QString& campaignAxis);

    QComboBox* formatBox() const { return m_format; }
    QLineEdit* axisEdit() const { return m_axis; }
    QSpinBox* magnificationBox() const { return m_magnification; }
    QLineEdit* pathEdit() const { return m_path; }
    QPushButton* exportButton() const { return m_export; }

signals:
    /// After an export: the file and its warnings, or the error (file empty).
    void exported(const QString& path, const QStringList& warnings);
    void exportFailed(const QString& error);

public slots:
    /// Writes the table in the chosen format to the path field's file.
    void exportNow();

private:
    void browse();

    QComboBox* m_format;
    QLineEdit* m_axis;
    QSpinBox* m_magnification;
    QLineEdit* m_path;
    QPushButton* m_browse;
    QPushButton* m_export;
    std::optional<compensation::CompensationTable> m_table;
    QString m_campaignAxis;
};

}  // namespace driftlab::ui
