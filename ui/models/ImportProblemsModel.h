#pragma once
// Why an import was refused, one row per message: its level (error, warning),
// the file, line and column it names and what is wrong there. The readers
// report "file:line:column: why" (bundle::BundleError::toString); the model
// splits that so a long list sorts and reads by file and line.

#include <QAbstractTableModel>
#include <QStringList>
#include <vector>

namespace driftlab::ui {

struct ImportProblem {
    QString level;  ///< "error" or "warning"
    QString file;
    int line = 0;    ///< 0: the message names no line
    int column = 0;  ///< 0: the message names no column
    QString message;
};

/// "file:line:column: why" (line and column optional) split into its parts;
/// a message naming no place keeps it all in `message`.
ImportProblem parseImportProblem(const QString& level, const QString& text);

class ImportProblemsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Level, File, Line, Column, Message };

    explicit ImportProblemsModel(QObject* parent = nullptr);

    /// The refusal's errors first, then the warnings read on the way; files
    /// inside `bundle` are shown relative to it (samples.csv, not its whole path).
    void setProblems(const QStringList& errors, const QStringList& warnings,
                     const QString& bundle = {});
    const ImportProblem& problem(int row) const { return m_problems[std::size_t(row)]; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    std::vector<ImportProblem> m_problems;
};

}  // namespace driftlab::ui
