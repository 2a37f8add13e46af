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
        case Gain:
            return QString::number(100 * f.reduction, 'f', 1);
        case RmsAfter:
            return QString::number(f.test_after.error_rms_um, 'f', 2);
        case BicDrop:
            return QString::number(f.bic_drop, 'f', 0);
        case Parameter:
            return QStringLiteral("%1 = %2 ± %3 %4")
                .arg(f.parameter_name)
                .arg(f.parameter.value, 0, 'g', 4)
                .arg(std::isfinite(f.parameter.sigma) ? QString::number(f.parameter.sigma, 'g', 2)
                                                      : QStringLiteral("?"))
                .arg(f.parameter.unit);
        case Evidence:
            return f.evidence;
        default:
            return {};
    }
}

QVariant FindingsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Cause:
            return tr("Cause");
        case Significant:
            return tr("Significant");
        case Gain:
            return tr("Held-out gain (%)");
        case RmsAfter:
            return tr("RMS after (µm)");
        case BicDrop:
            return tr("ΔBIC");
        case Parameter:
            return tr("Parameter ± σ");
        case Evidence:
            return tr("Evidence");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
