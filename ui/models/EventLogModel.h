#pragma once
// The event log dock: what the devices, the engine and the jobs report, one
// row per incident (the device workers report an outage once, and its gap
// when it ends), newest last, at most `capacity` rows.

#include <QAbstractTableModel>
#include <QDateTime>
#include <deque>

namespace driftlab::ui {

class EventLogModel : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit EventLogModel(int capacity = 10'000, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

public slots:
    /// level: info, warning or error.
    void append(const QString& level, const QString& source, const QString& message);

private:
    struct Entry {
        QDateTime time;
        QString level, source, message;
    };
    std::deque<Entry> m_entries;
    int m_capacity;
};

}  // namespace driftlab::ui
