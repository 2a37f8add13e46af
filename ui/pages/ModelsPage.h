#pragma once
// The Models page, the model workbench (docs/gui-models.md): fit any model
// family on chosen training runs and score it on held-out runs (parameters
// with σ and units, scores per run, stored with the campaign), predictions
// against measurements, and the cross-state matrix of every model. Every fit
// and comparison runs off the GUI thread with progress and Cancel.

#include <QWidget>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTableView;

namespace driftlab::ui {

class BackgroundJob;
class CrossStateMatrixModel;
class FitSetupPanel;
class ModelParametersModel;
class PredictionPlotWidget;
class Session;
class TestScoresModel;
struct FitOutcome;
struct CompareOutcome;

class ModelsPage : public QWidget {
    Q_OBJECT
public:
    explicit ModelsPage(Session& session, QWidget* parent = nullptr);
    ~ModelsPage() override;

    FitSetupPanel* setupPanel() const { return m_setup; }
    QPushButton* fitButton() const { return m_fit; }
    QPushButton* compareButton() const { return m_compare; }
    QPushButton* cancelButton() const { return m_cancel; }
    QTabWidget* resultTabs() const { return m_tabs; }
    BackgroundJob* job() const { return m_job; }
    /// The last outcome line ("fitted …", "cancelled", an error).
    QString status() const;
    /// The last fit's notes as shown: the model's, what was left out, and
    /// where the test runs leave the training runs' temperature rises.
    QString notes() const;
    ModelParametersModel* parametersModel() const { return m_parameters; }
    TestScoresModel* scoresModel() const { return m_scores; }
    CrossStateMatrixModel* matrixModel() const { return m_matrix; }
    PredictionPlotWidget* predictions() const { return m_predictions; }

public slots:
    void fit();
    void compare();
    void cancel();
    /// Re-reads the selected campaign's runs (after a campaign or store change).
    void reload();

private:
    QWidget* buildFitTab();
    QWidget* buildMatrixTab();
    void showFit(const FitOutcome& outcome, const QString& model);
    void showComparison(const CompareOutcome& outcome);
    void setBusy(bool busy);
    bool reloadIfPending();
    void updateButtons();
    void report(const QString& level, const QString& message);

    Session& m_session;
    BackgroundJob* m_job;
    bool m_reloadPending = false;
    bool m_listsLoaded = false;
    FitSetupPanel* m_setup;
    QPushButton *m_fit, *m_compare, *m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    QTabWidget* m_tabs;
    QLabel* m_fitSummary;
    QLabel* m_notes;
    ModelParametersModel* m_parameters;
    TestScoresModel* m_scores;
    CrossStateMatrixModel* m_matrix;
    QTableView* m_matrixView;
    QLabel* m_matrixLegend;
    PredictionPlotWidget* m_predictions;
};

}  // namespace driftlab::ui
