#pragma once
// The ISO 230-2 results page (docs/iso230.md, docs/gui-compensation.md): a
// run's positioning readings evaluated as `driftlab-cli iso230-2` does, the
// per-target table, the axis figures and the mean ± k·s plot for both
// directions, with the evaluation's warnings; the acceptance against the
// tolerances of a specification (docs/acceptance.md), which the user loads,
// edits and saves.

#include <QWidget>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/PositioningAcceptance.h"
#include "ui/widgets/CampaignLoad.h"

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPlainTextEdit;
class QTableView;

namespace driftlab::ui {

class SelectedCampaignLoader;

class AcceptanceModel;
class Iso230_2Plot;
class Iso230_2TargetModel;
class MachineHistoryView;
class Session;

class Iso230_2Page : public QWidget {
    Q_OBJECT
public:
    explicit Iso230_2Page(Session& session, QWidget* parent = nullptr);
    ~Iso230_2Page() override;

    QComboBox* runBox() const { return m_run; }
    QComboBox* editionBox() const { return m_edition; }
    QDoubleSpinBox* coverageBox() const { return m_coverage; }
    Iso230_2TargetModel* targetModel() const { return m_model; }
    Iso230_2Plot* plot() const { return m_plot; }
    /// The "Machine history" tab: every stored campaign of the campaign's machine axis.
    MachineHistoryView* historyView() const { return m_history; }
    /// The axis figure labelled `key` (B, B_mean, R_up, …, A, as in
    /// `iso230-2 --json`), as shown; empty for an unknown key.
    QString figureText(const QString& key) const;
    QLabel* messageLabel() const { return m_message; }
    QLabel* warningLabel() const { return m_warnings; }
    const std::optional<iso::Evaluation>& evaluation() const { return m_evaluation; }

    /// The "Acceptance" tab: tolerances (editable) and verdicts.
    AcceptanceModel* acceptanceModel() const { return m_acceptanceModel; }
    const std::optional<iso::PositioningAcceptance>& acceptance() const { return m_acceptance; }
    QLabel* specificationLabel() const { return m_specSource; }
    /// Uses the specification file at `path` (what "Open specification…"
    /// does); false with the reason shown when it cannot be read.
    bool loadSpecification(const QString& path);
    /// Writes the specification with the tolerances as edited ("Save
    /// specification…"); false with the reason shown when it cannot be written.
    bool saveSpecification(const QString& path);

signals:
    void evaluated();

private:
    void onLoaded(const LoadedCampaign& loaded);
    void evaluateRun();
    void showError(const QString& message);
    void applyEditedTolerances();
    QWidget* acceptanceTab();

    Session& m_session;
    QComboBox* m_run;
    QComboBox* m_edition;
    QDoubleSpinBox* m_coverage;
    QLabel* m_message;
    QLabel* m_warnings;
    QTableView* m_view;
    Iso230_2TargetModel* m_model;
    Iso230_2Plot* m_plot;
    MachineHistoryView* m_history;
    QGridLayout* m_figures;
    std::vector<std::pair<QString, QLabel*>> m_figureLabels;
    SelectedCampaignLoader* m_loader;
    std::optional<Campaign> m_campaign;
    std::optional<iso::Evaluation> m_evaluation;
    AcceptanceModel* m_acceptanceModel;
    QLabel* m_specSource;
    QPlainTextEdit* m_acceptanceText;
    /// The specification in use: the campaign's own, a file's, or made by
    /// typing a tolerance; nullopt: the readings as measured, no verdict.
    std::optional<iso::AcceptanceSpecification> m_spec;
    std::optional<iso::PositioningAcceptance> m_acceptance;
};

}  // namespace driftlab::ui
