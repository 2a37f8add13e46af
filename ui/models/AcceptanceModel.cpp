#include "ui/models/AcceptanceModel.h"

#include <QColor>
#include <cmath>

namespace driftlab::ui {

namespace {

QString um(double value) {
    return std::isfinite(value) ? QString::number(value, 'f', 3) : QStringLiteral("n/a");
}

QColor verdictColour(iso::Verdict verdict) {
    switch (verdict) {
        case iso::Verdict::Pass:
            return QColor(0x20, 0x80, 0x30);
        case iso::Verdict::Fail:
            return QColor(0xb0, 0x00, 0x00);
        case iso::Verdict::NotProven:
        case iso::Verdict::NotDetermined:
            return QColor(0xa0, 0x50, 0x00);
    }
    return {};
}

}  // namespace

AcceptanceModel::AcceptanceModel(QObject* parent) : QAbstractTableModel(parent) {}

void AcceptanceModel::setTolerances(std::map<QString, double> tolerances_um) {
    beginResetModel();
    m_tolerances = std::move(tolerances_um);
    endResetModel();
}

void AcceptanceModel::setAcceptance(std::optional<iso::PositioningAcceptance> acceptance) {
    beginResetModel();
    m_acceptance = std::move(acceptance);
    endResetModel();
}

int AcceptanceModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(iso::iso230_2ParameterKeys().size());
}

int AcceptanceModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : Verdict + 1;
}

const iso::Decision* AcceptanceModel::decisionOf(const QString& parameter) const {
    if (!m_acceptance) return nullptr;
    for (const iso::Decision& d : m_acceptance->decisions)
        if (d.parameter == parameter) return &d;
    return nullptr;
}

QVariant AcceptanceModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const QString key = iso::iso230_2ParameterKeys().at(index.row());
    const auto tolerance = m_tolerances.find(key);
    const iso::Decision* decision = decisionOf(key);
    const double result_um =
        m_acceptance ? iso::axisValue(m_acceptance->evaluation.axis, key) : std::nan("");
    const iso::ParameterUncertainty* u = m_acceptance ? m_acceptance->budget.find(key) : nullptr;
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
            case Value:
                return key;
            case Tolerance:
                if (tolerance == m_tolerances.end()) return QString();
                return role == Qt::EditRole ? QVariant(tolerance->second)
                                            : QVariant(um(tolerance->second));
            case Result:
                return m_acceptance ? um(result_um) : QString();
            case Uncertainty:
                return u ? um(u->expanded_um) : QString();
            case Margin:
                return decision ? um(decision->margin_um) : QString();
            case Verdict:
                return decision ? iso::toString(decision->verdict) : QString();
        }
    }
    if (role == Qt::ForegroundRole && index.column() == Verdict && decision)
        return verdictColour(decision->verdict);
    if (role == Qt::TextAlignmentRole && index.column() != Value && index.column() != Verdict)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && index.column() == Tolerance)
        return tr("Upper tolerance in µm; empty for none");
    return {};
}

bool AcceptanceModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.column() != Tolerance || role != Qt::EditRole) return false;
    const QString key = iso::iso230_2ParameterKeys().at(index.row());
    const QString text = value.toString().trimmed();
    if (text.isEmpty()) {
        m_tolerances.erase(key);
    } else {
        bool ok = false;
        const double tolerance_um = QLocale().toDouble(text, &ok);
        const double parsed_um = ok ? tolerance_um : text.toDouble(&ok);
        if (!ok || !std::isfinite(parsed_um) || parsed_um <= 0) return false;
        m_tolerances[key] = parsed_um;
    }
    emit dataChanged(index, index);
    emit tolerancesEdited();
    return true;
}

Qt::ItemFlags AcceptanceModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() == Tolerance) f |= Qt::ItemIsEditable;
    return f;
}

QVariant AcceptanceModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Value:
            return tr("Value");
        case Tolerance:
            return tr("Tolerance µm");
        case Result:
            return tr("Result µm");
        case Uncertainty:
            return tr("U µm");
        case Margin:
            return tr("Margin µm");
        case Verdict:
            return tr("Verdict");
    }
    return {};
}

}  // namespace driftlab::ui
