#pragma once
// What the window works on: the open store and the selected campaign. Pages
// read the store through it (read-only connections of their own, opened per
// request) and tell it when they changed something, so the campaign tree and
// the other pages refresh. Lives on the GUI thread.

#include <QObject>
#include <QString>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/procedures/Procedure.h"

namespace driftlab::ui {

/// What the Set-up page prepares and the Run page runs: the procedure and
/// the rig it runs on (the options of `driftlab-cli run`).
struct RunSetup {
    procedures::Procedure procedure;
    QString procedure_path;               ///< where it was read from, if from a file
    QString rig = QStringLiteral("sim");  ///< "sim" or "modbus"
    // Simulated rig
    unsigned seed = 1;
    QStringList effects;  ///< ID=VALUE, as `simulate --effect`
    double speedup = 600;
    // Modbus rig
    QString temperature_url;  ///< modbus://HOST:PORT or modbus-rtu:///dev/…
    QString device_map_path;
    QString controller_url;      ///< empty: none
    QString interferometer_url;  ///< tcp://HOST:PORT, empty: none
    /// Machine, screw, travel, interferometer and channels (ids as in the
    /// device map, with roles) for a real rig; the simulated rig has its own.
    std::optional<Campaign> machine;
};

class Session : public QObject {
    Q_OBJECT
public:
    explicit Session(QObject* parent = nullptr);

    QString storePath() const { return m_storePath; }
    std::optional<qint64> campaignId() const { return m_campaignId; }
    /// The selected campaign as stored; nullopt with `error` when none is
    /// selected or it cannot be read.
    std::optional<Campaign> loadCampaign(QString* error) const;
    const RunSetup& runSetup() const { return m_runSetup; }

public slots:
    /// Opens (or, `create`, creates) a store: a SQLite file or a lab store's
    /// postgresql:// URL (never created here); false with `error`.
    bool openStore(const QString& path, bool create, QString* error);
    void selectCampaign(std::optional<qint64> id);
    /// Something was added to the store (a run, a fit, a table): views refresh.
    void notifyStoreChanged();
    void setRunSetup(const RunSetup& setup);

signals:
    void storeChanged(const QString& path);
    void campaignSelected(std::optional<qint64> id);
    void storeContentChanged();
    void runSetupChanged();
    /// A message for the event log (level: info, warning, error).
    void event(const QString& level, const QString& source, const QString& message);

private:
    QString m_storePath;
    std::optional<qint64> m_campaignId;
    RunSetup m_runSetup;
};

}  // namespace driftlab::ui
