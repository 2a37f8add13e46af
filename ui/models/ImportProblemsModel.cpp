#include "ui/models/ImportProblemsModel.h"

#include <QBrush>
#include <QColor>
#include <QRegularExpression>

namespace driftlab::ui {

ImportProblem parseImportProblem(const QString& level, const QString& text) {
    // Non-greedy file: the first ":digits" ends it, so "C:/x/samples.csv:3:5"
    // would split wrongly only on a drive letter followed by digits.
    static const QRegularExpression where(QStringLiteral(R"(^(.+?)(?::(\d+))?(?::(\d+))?: (.*)$)"),
                                          QRegularExpression::DotMatchesEverythingOption);
    const QRegularExpressionMatch m = where.match(text);
    if (!m.hasMatch()) return {level, {}, 0, 0, text};
    return {level, m.captured(1), m.captured(2).toInt(), m.captured(3).toInt(), m.captured(4)};
}

ImportProblemsModel::ImportProblemsModel(QObject* parent) : QAbstractTableModel(parent) {}

void ImportProblemsModel::setProblems(const QStringList& errors, const QStringList& warnings,
                                      const QString& bundle) {
    beginResetModel();
    m_problems.clear();
    const QString prefix = bundle.isEmpty() ? QString() : bundle + QLatin1Char('/');
    auto add = [&](const QString& level, const QString& text) {
        ImportProblem p = parseImportProblem(level, text);
        if (!prefix.isEmpty() && p.file.startsWith(prefix)) p.file.remove(0, prefix.size());
        m_problems.push_back(std::move(p));
    };
    for (const QString& e : errors) add(QStringLiteral("error"), e);
    for (const QString& w : warnings) add(QStringLiteral("warning"), w);
    endResetModel();
}

int ImportProblemsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_problems.size());
}

int ImportProblemsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 5;
}

QVariant ImportProblemsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const ImportProblem& p = m_problems[std::size_t(index.row())];
    if (role == Qt::ForegroundRole && index.column() == Level)
        return QBrush(p.level == QLatin1String("error") ? QColor(0xb0, 0x20, 0x20)
                                                        : QColor(0x9a, 0x60, 0x00));
    if (role == Qt::ToolTipRole) return p.message;
    if (role != Qt::DisplayRole) return {};
    auto number = [](int n) { return n > 0 ? QVariant(n) : QVariant(); };
    switch (index.column()) {
        case Level:
            return p.level;
        case File:
            return p.file;
        case Line:
            return number(p.line);
        case Column:
            return number(p.column);
        case Message:
            return p.message;
        default:
            return {};
    }
}

QVariant ImportProblemsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Level:
            return tr("Level");
        case File:
            return tr("File");
        case Line:
            return tr("Line");
        case Column:
            return tr("Column");
        case Message:
            return tr("Problem");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
