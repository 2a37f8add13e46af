#include "ui/models/EventLogModel.h"

#include <QBrush>
#include <QColor>

namespace driftlab::ui {

EventLogModel::EventLogModel(int capacity, QObject* parent)
    : QAbstractTableModel(parent), m_capacity(std::max(1, capacity)) {}

int EventLogModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_entries.size());
}

int EventLogModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 4;
}

QVariant EventLogModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_entries.size())) return {};
    const Entry& e = m_entries[std::size_t(index.row())];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
            case 0:
                return e.time.toLocalTime().toString(QStringLiteral("HH:mm:ss"));
            case 1:
                return e.level;
            case 2:
                return e.source;
            case 3:
                return e.message;
        }
    }
    if (role == Qt::ForegroundRole && index.column() == 1) {
        if (e.level == QLatin1String("error")) return QBrush(QColor(0xc0, 0x20, 0x20));
        if (e.level == QLatin1String("warning")) return QBrush(QColor(0xb0, 0x70, 0x00));
    }
    if (role == Qt::ToolTipRole) return e.message;
    return {};
}

QVariant EventLogModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    static const char* names[] = {"Time", "Level", "Source", "Message"};
    return section >= 0 && section < 4 ? tr(names[section]) : QVariant();
}

void EventLogModel::append(const QString& level, const QString& source, const QString& message) {
    if (int(m_entries.size()) == m_capacity) {
        beginRemoveRows({}, 0, 0);
        m_entries.pop_front();
        endRemoveRows();
    }
    const int row = int(m_entries.size());
    beginInsertRows({}, row, row);
    m_entries.push_back({QDateTime::currentDateTimeUtc(), level, source, message});
    endInsertRows();
}

}  // namespace driftlab::ui
