#pragma once
// The Compensation page (docs/gui-compensation.md):
// a pitch-error table from a positioning run of the selected campaign (the
// ISO 230-2 mean deviations, as `driftlab-cli compensate`), its plot, the
// difference to the controller's active table, export to every table format,
// and the push with its confirmation and history (ControllerPanel).

#include <QWidget>
#include <optional>

#include "core/compensation/CompensationTable.h"
#include "core/domain/Campaign.h"
#include "ui/widgets/CampaignLoad.h"

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSpinBox;
class QTableView;

namespace driftlab::ui {

class SelectedCampaignLoader;

class CompensationPlot;
class CompensationTableModel;
class ControllerPanel;
class Session;
class TableExportPanel;

class CompensationPage : public QWidget {
    Q_OBJECT
public:
    explicit CompensationPage(Session& session, QWidget* parent = nullptr);
    ~CompensationPage() override;

    QComboBox* runBox() const { return m_run; }
    QRadioButton* perTargetButton() const { return m_perTarget; }
    QRadioButton* spacingButton() const { return m_bySpacing; }
    QRadioButton* pointsButton() const { return m_byPoints; }
    QDoubleSpinBox* spacingBox() const { return m_spacing; }
    QSpinBox* pointsBox() const { return m_points; }
    QCheckBox* bidirectionalBox() const { return m_bidirectional; }
    CompensationTableModel* tableModel() const { return m_model; }
    CompensationPlot* plot() const { return m_plot; }
    TableExportPanel* exportPanel() const { return m_export; }
    ControllerPanel* controllerPanel() const { return m_controller; }
    /// The line under the settings: what the table is, or what went wrong.
    QLabel* messageLabel() const { return m_message; }

signals:
    /// The campaign is loaded and the table built (or refused: see messageLabel()).
    void tableUpdated();

private:
    void clearCampaign();
    void onLoaded(const LoadedCampaign& loaded);
    void rebuild();
    void showError(const QString& message);

    Session& m_session;
    QComboBox* m_run;
    QButtonGroup* m_layoutChoice;
    QRadioButton* m_perTarget;
    QRadioButton* m_bySpacing;
    QRadioButton* m_byPoints;
    QDoubleSpinBox* m_spacing;
    QSpinBox* m_points;
    QCheckBox* m_bidirectional;
    QLabel* m_message;
    QTableView* m_view;
    CompensationTableModel* m_model;
    CompensationPlot* m_plot;
    TableExportPanel* m_export;
    ControllerPanel* m_controller;
    SelectedCampaignLoader* m_loader;
    std::optional<Campaign> m_campaign;
};

}  // namespace driftlab::ui
