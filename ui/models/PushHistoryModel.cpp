#include "ui/models/PushHistoryModel.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>
#include <algorithm>

namespace driftlab::ui {

PushHistoryModel::PushHistoryModel(QObject* parent) : QAbstractTableModel(parent) {}

void PushHistoryModel::setPushes(std::vector<db::PushRecord> pushes) {
    beginResetModel();
    m_pushes = std::move(pushes);
    std::reverse(m_pushes.begin(), m_pushes.end());
    endResetModel();
}

int PushHistoryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_pushes.size());
}

int PushHistoryModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : Message + 1;
}

QVariant PushHistoryModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const db::PushRecord& p = m_pushes[std::size_t(index.row())];
    if (role == Qt::ForegroundRole && index.column() == Result)
        return QBrush(p.result == QLatin1String("applied") ? QColor(0x20, 0x80, 0x20)
                                                           : QColor(0xc0, 0x20, 0x20));
    if (role == Qt::ToolTipRole && index.column() == Message) return p.message;
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case PushedAt: {
            // Stored in UTC; the engineer reads local time.
            const QDateTime at = QDateTime::fromString(p.pushed_at, Qt::ISODate);
            return at.isValid() ? at.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"))
                                : p.pushed_at;
        }
        case Run:
            return p.run;
        case Controller:
            return p.controller_url;
        case Version:
            return p.table_version;
        case Points:
            return p.points;
        case Checksum:
            return QStringLiteral("0x%1").arg(p.table_checksum, 4, 16, QLatin1Char('0'));
        case Result:
            return p.result;
        case Message:
            return p.message;
        default:
            return {};
    }
}

QVariant PushHistoryModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    switch (section) {
        case PushedAt:
            return tr("Pushed at");
        case Run:
            return tr("Run");
        case Controller:
            return tr("Controller");
        case Version:
            return tr("Version");
        case Points:
            return tr("Points");
        case Checksum:
            return tr("Checksum");
        case Result:
            return tr("Result");
        case Message:
            return tr("Message");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
