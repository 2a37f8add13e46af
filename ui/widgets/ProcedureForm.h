#pragma once
// Set-up section "Procedure": pick a shipped procedure (compiled in from
// resources/procedures) or open a file, see its kind, runs and durations
// (procedures::planRuns), change its key numbers, or edit its JSON. Every
// change is read back through procedures::parseProcedure, so an error names
// the key path ("procedure.sample_interval_s: must be > 0").

#include <QWidget>
#include <optional>
#include <vector>

#include "core/procedures/Procedure.h"
#include "ui/widgets/ProcedureKeyNumbers.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPlainTextEdit;
class QTableWidget;

namespace driftlab::ui {

class ProcedureForm : public QWidget {
    Q_OBJECT
public:
    explicit ProcedureForm(QWidget* parent = nullptr);

    /// The procedures shipped with DriftLab, as resource paths (":/procedures/…").
    static QStringList shippedProcedures();

    /// Reads a procedure file (or a shipped one); false with `error`.
    bool loadFile(const QString& path, QString* error);
    void setProcedure(const procedures::Procedure& procedure, const QString& path);
    /// The procedure as it stands now; nullopt when the JSON does not read.
    const std::optional<procedures::Procedure>& procedure() const { return m_procedure; }
    QString path() const { return m_path; }
    /// The reason the procedure does not read or plan (empty: it is fine).
    QString error() const { return m_error; }
    /// Appends "Procedure → …" lines to `summary`.
    void validate(QStringList& summary) const;
    /// The simulated rig's speed-up, for the "about … at speed-up" line; 0: real time.
    void setSpeedup(double speedup);

    QComboBox* source;
    QPlainTextEdit* json;
    /// The key number spin boxes of the current kind, in keyNumbersOf() order.
    std::vector<QDoubleSpinBox*> keyBoxes;

signals:
    void procedureChanged();
    /// A file could not be read (for the event log).
    void loadFailed(const QString& error);

private:
    void openFile();
    void readJson();
    void rebuildKeyNumbers();
    void writeJson();
    void showSummary();

    std::optional<procedures::Procedure> m_procedure;
    /// The last procedure that read, which the key numbers edit.
    std::optional<procedures::Procedure> m_lastGood;
    QString m_path;
    QString m_error;
    double m_speedup = 0;
    bool m_writing = false;
    std::vector<ProcedureKeyNumber> m_keyNumbers;
    std::optional<procedures::ProcedureKind> m_keyKind;
    QFormLayout* m_keyForm;
    QLabel* m_kind;
    QLabel* m_total;
    QLabel* m_errorLabel;
    QTableWidget* m_runs;
};

}  // namespace driftlab::ui
