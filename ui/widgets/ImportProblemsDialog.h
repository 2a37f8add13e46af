#pragma once
// Shown when an import is refused: what was not imported, that the store was
// left as it was, and the reader's messages as a table (file, line, column,
// problem) the engineer can fix the file from.

#include <QDialog>

class QLabel;
class QTableView;

namespace driftlab::ui {

class ImportProblemsModel;

class ImportProblemsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ImportProblemsDialog(QWidget* parent = nullptr);

    /// `source`: what was being imported; `store`: where nothing was stored.
    void showProblems(const QString& source, const QString& store, const QStringList& errors,
                      const QStringList& warnings);
    ImportProblemsModel* model() const { return m_model; }
    QString summary() const;

private:
    ImportProblemsModel* m_model;
    QLabel* m_summary;
    QTableView* m_view;
};

}  // namespace driftlab::ui
