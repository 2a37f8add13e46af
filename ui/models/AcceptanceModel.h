#pragma once
// The ISO 230-2 page's acceptance table: one row per axis value (A, A↑, …, M)
// with its tolerance, which the user edits, and what the acceptance made of
// it: the result, its expanded uncertainty U, the margin and the verdict by
// ISO 14253-1 (docs/acceptance.md). An empty tolerance is none.

#include <QAbstractTableModel>
#include <map>
#include <optional>

#include "core/iso/PositioningAcceptance.h"

namespace driftlab::ui {

class AcceptanceModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Value, Tolerance, Result, Uncertainty, Margin, Verdict };

    explicit AcceptanceModel(QObject* parent = nullptr);

    /// The tolerances shown, in µm by JSON key ("A" → 12).
    void setTolerances(std::map<QString, double> tolerances_um);
    const std::map<QString, double>& tolerances() const { return m_tolerances; }
    /// The acceptance the tolerances led to; nullopt clears the result columns.
    void setAcceptance(std::optional<iso::PositioningAcceptance> acceptance);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    /// The user changed a tolerance (setTolerances does not emit it).
    void tolerancesEdited();

private:
    const iso::Decision* decisionOf(const QString& parameter) const;
    std::map<QString, double> m_tolerances;
    std::optional<iso::PositioningAcceptance> m_acceptance;
};

}  // namespace driftlab::ui
