#pragma once
// The health of each device of the run in progress, from the events its
// devices report (one per incident): green while it answers, amber after a
// warning, red from an error (lost) until the gap event says it is back.
// Rows: devices; columns: device, health, last message.

#include <QAbstractTableModel>
#include <QColor>
#include <vector>

namespace driftlab::ui {

enum class DeviceHealth { Ok, Warning, Lost };

class DeviceHealthModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { DeviceColumn, HealthColumn, MessageColumn, ColumnCount };
    static constexpr int HealthRole = Qt::UserRole + 1;

    using QAbstractTableModel::QAbstractTableModel;

    /// Starts over with these devices, all healthy.
    void reset(const QStringList& devices);
    /// A device event (level info, warning or error); an unknown source is added.
    void report(const QString& level, const QString& source, const QString& message);
    DeviceHealth health(int row) const { return m_rows.at(std::size_t(row)).health; }
    static QColor colourOf(DeviceHealth health);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    struct Row {
        QString device;
        DeviceHealth health = DeviceHealth::Ok;
        QString message;
    };
    std::vector<Row> m_rows;
};

}  // namespace driftlab::ui
