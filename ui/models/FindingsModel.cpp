#include "ui/models/FindingsModel.h"

#include <QFont>
#include <cmath>

namespace driftlab::ui {

FindingsModel::FindingsModel(QObject* parent) : QAbstractTableModel(parent) {}

void FindingsModel::setFindings(std::vector<diagnosis::Finding> findings, const QString& verdict) {
    beginResetModel();
    m_findings = std::move(findings);
    m_verdict = verdict;
    endResetModel();
}

const diagnosis::Finding* FindingsModel::finding(int row) const {
    return row >= 0 && row < int(m_findings.size()) ? &m_findings[std::size_t(row)] : nullptr;
}

int FindingsModel::verdictRow() const {
    for (std::size_t k = 0; k < m_findings.size(); ++k)
        if (m_findings[k].cause == m_verdict) return int(k);
    return -1;
}

int FindingsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_findings.size());
}

int FindingsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant FindingsModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const diagnosis::Finding& f = m_findings[std::size_t(index.row())];
    if (role == Qt::FontRole) {
        QFont font;
        font.setBold(f.cause == m_verdict);
        return font;
    }
    if (role == Qt::ToolTipRole) return f.evidence;
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Cause:
            return f.cause;
        case Significant:
            return f.significant ? tr("yes") : tr("no");
        case Confidence:
            return QString::number(f.confidence, 'f', 2);
        case Gain:
            return QString::number(100 * f.gain.reduction, 'f', 1);
        case RmsAfter:
            return QStringLiteral("%1 %2")
                .arg(f.gain.test_rms_after, 0, 'f', f.gain.unit == QLatin1String("K") ? 3 : 2)
                .arg(f.gain.unit);
        case BicDrop:
            return QString::number(f.bic_drop, 'f', 0);
        case Parameter:
            return diagnosis::parametersText(f);
        case Evidence:
            return f.evidence;
        default:
            return {};
    }
}

QVariant FindingsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal) return {};
    if (role == Qt::ToolTipRole && section == Confidence)
        return tr(
            "The probability that the held-out gain is real and larger than every other "
            "candidate's of its step; for a cause named, times the share of the positioning "
            "structure above the noise that the causes explain");
    if (role != Qt::DisplayRole) return {};
    switch (section) {
        case Cause:
            return tr("Cause");
        case Significant:
            return tr("Significant");
        case Confidence:
            return tr("Confidence");
        case Gain:
            return tr("Held-out gain (%)");
        case RmsAfter:
            return tr("Held-out RMS after");
        case BicDrop:
            return tr("ΔBIC");
        case Parameter:
            return tr("Parameters ± σ");
        case Evidence:
            return tr("Evidence");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
