#pragma once
// What the window works on: the open store and the selected campaign. Pages
// read the store through it (read-only connections of their own, opened per
// request) and tell it when they changed something, so the campaign tree and
// the other pages refresh. Lives on the GUI thread.

#include <QObject>
#include <QString>
#include <optional>

#include "core/domain/Campaign.h"

namespace driftlab::ui {

class Session : public QObject {
    Q_OBJECT
public:
    explicit Session(QObject* parent = nullptr);

    QString storePath() const { return m_storePath; }
    std::optional<qint64> campaignId() const { return m_campaignId; }
    /// The selected campaign as stored; nullopt with `error` when none is
    /// selected or it cannot be read.
    std::optional<Campaign> loadCampaign(QString* error) const;

public slots:
    /// Opens (or, `create`, creates) a store; false with `error`.
    bool openStore(const QString& path, bool create, QString* error);
    void selectCampaign(std::optional<qint64> id);
    /// Something was added to the store (a run, a fit, a table): views refresh.
    void notifyStoreChanged();

signals:
    void storeChanged(const QString& path);
    void campaignSelected(std::optional<qint64> id);
    void storeContentChanged();
    /// A message for the event log (level: info, warning, error).
    void event(const QString& level, const QString& source, const QString& message);

private:
    QString m_storePath;
    std::optional<qint64> m_campaignId;
};

}  // namespace driftlab::ui
