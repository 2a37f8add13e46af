#pragma once
// The Diagnosis page (docs/diagnosis.md and docs/gui-models.md): diagnose the selected
// campaign off the GUI thread (progress, Cancel), show the verdict, the
// findings with their evidence, the residual map and the before/after curves
// of each held-out run, adopt an extension (kept as a model fit, as
// `driftlab-cli diagnose --db` keeps the verdict's), and list the diagnoses
// stored for the campaign.

#include <QWidget>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;

namespace driftlab::ui {

class BackgroundJob;
class FindingsModel;
class PlotView;
class Session;
class StoredDiagnosesModel;
struct DiagnosisOutcome;

class DiagnosisPage : public QWidget {
    Q_OBJECT
public:
    explicit DiagnosisPage(Session& session, QWidget* parent = nullptr);
    ~DiagnosisPage() override;

    QPushButton* diagnoseButton() const { return m_diagnose; }
    QPushButton* cancelButton() const { return m_cancel; }
    QPushButton* adoptButton() const { return m_adopt; }
    QTableView* findingsView() const { return m_findingsView; }
    BackgroundJob* job() const { return m_job; }
    QString status() const;
    QString verdict() const;
    FindingsModel* findingsModel() const { return m_findings; }
    StoredDiagnosesModel* storedModel() const { return m_stored; }
    PlotView* residualMap() const { return m_map; }
    PlotView* beforeAfter() const { return m_curves; }

public slots:
    void diagnose();
    void cancel();
    /// Keeps the selected finding's extension (the verdict's by default).
    void adopt();
    void refreshStored();

private:
    void show(const DiagnosisOutcome& outcome);
    void drawPlots();
    void setBusy(bool busy);
    void report(const QString& level, const QString& message);
    void campaignChanged();

    Session& m_session;
    BackgroundJob* m_job;
    std::shared_ptr<const DiagnosisOutcome> m_outcome;
    std::optional<int> m_adoptedFinding;  ///< row whose extension was adopted
    QPushButton *m_diagnose, *m_cancel, *m_adopt;
    QProgressBar* m_progress;
    QLabel *m_status, *m_verdict;
    FindingsModel* m_findings;
    QTableView* m_findingsView;
    StoredDiagnosesModel* m_stored;
    QComboBox* m_run;
    PlotView *m_map, *m_curves;
};

}  // namespace driftlab::ui
