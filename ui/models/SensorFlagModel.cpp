#include "ui/models/SensorFlagModel.h"

#include <QBrush>
#include <QColor>

namespace driftlab::ui {

SensorFlagModel::SensorFlagModel(QObject* parent) : QAbstractTableModel(parent) {}

void SensorFlagModel::setFlags(std::vector<ShownFlag> flags) {
    beginResetModel();
    m_flags = std::move(flags);
    endResetModel();
}

int SensorFlagModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_flags.size());
}

int SensorFlagModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : InFits + 1;
}

QVariant SensorFlagModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_flags.size())) return {};
    const ShownFlag& shown = m_flags[std::size_t(index.row())];
    const sensors::FlaggedRange& r = shown.flag.range;
    if (role == Qt::UserRole) {
        switch (index.column()) {
            case Channel:
                return shown.flag.id;
            case Kind:
                return sensors::toString(r.fault);
            case From:
                return r.from_s;
            case To:
                return r.to_s;
            case Samples:
                return qulonglong(shown.samples);
            case InFits:
                return shown.flag.kept;
        }
        return {};
    }
    if (role == Qt::ForegroundRole && index.column() == InFits)
        return QBrush(shown.flag.kept ? QColor(0x1a, 0x7f, 0x37) : QColor(0xb0, 0x00, 0x00));
    if (role == Qt::TextAlignmentRole && index.column() >= From && index.column() <= Samples)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Channel:
            return r.channel;
        case Kind:
            return sensors::toString(r.fault);
        case From:
            return QString::number(r.from_s, 'f', 1);
        case To:
            return QString::number(r.to_s, 'f', 1);
        case Samples:
            return qulonglong(shown.samples);
        case InFits:
            return shown.flag.kept ? tr("kept: used") : tr("left out");
    }
    return {};
}

QVariant SensorFlagModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Channel:
            return tr("Channel");
        case Kind:
            return tr("Flag");
        case From:
            return tr("From s");
        case To:
            return tr("To s");
        case Samples:
            return tr("Samples");
        case InFits:
            return tr("In fits");
    }
    return {};
}

}  // namespace driftlab::ui
