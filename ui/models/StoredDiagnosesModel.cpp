#include "ui/models/StoredDiagnosesModel.h"

#include <QJsonArray>

namespace driftlab::ui {
namespace {

QString runs(const QJsonObject& result, const QString& key) {
    QStringList ids;
    for (const auto& v : result[key].toArray()) ids << v.toString();
    return ids.join(QLatin1Char(','));
}

}  // namespace

StoredDiagnosesModel::StoredDiagnosesModel(QObject* parent) : QAbstractTableModel(parent) {}

void StoredDiagnosesModel::setDiagnoses(std::vector<db::DiagnosisRecord> records) {
    beginResetModel();
    m_records = std::move(records);
    endResetModel();
}

int StoredDiagnosesModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_records.size());
}

int StoredDiagnosesModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant StoredDiagnosesModel::data(const QModelIndex& index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const db::DiagnosisRecord& d = m_records[std::size_t(index.row())];
    if (role == Qt::ToolTipRole) return d.result[QStringLiteral("verdict_evidence")].toString();
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
        case Id:
            return d.id;
        case Verdict:
            return d.verdict;
        case TrainRuns:
            return runs(d.result, QStringLiteral("train_runs"));
        case TestRuns:
            return runs(d.result, QStringLiteral("test_runs"));
        case BaseRms: {
            const QJsonValue v =
                d.result[QStringLiteral("base")].toObject()[QStringLiteral("test_rms_um")];
            return v.isDouble() ? QString::number(v.toDouble(), 'f', 2) : QStringLiteral("—");
        }
        case AdoptedFit:
            return d.adopted_fit_id ? QString::number(*d.adopted_fit_id) : QStringLiteral("—");
        default:
            return {};
    }
}

QVariant StoredDiagnosesModel::headerData(int section, Qt::Orientation orientation,
                                          int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Id:
            return tr("Id");
        case Verdict:
            return tr("Verdict");
        case TrainRuns:
            return tr("Trained on");
        case TestRuns:
            return tr("Held out");
        case BaseRms:
            return tr("Base RMS (µm)");
        case AdoptedFit:
            return tr("Adopted fit");
        default:
            return {};
    }
}

}  // namespace driftlab::ui
