#pragma once
// The Set-up page (docs/gui-setup.md): machine, screw, travel and
// interferometer, channels, procedure and rig, each a section of a list on
// the left. Every field is checked with a message beside it and a summary
// below; "Apply" stores the RunSetup in the Session only when nothing is
// wrong. The machine set-up loads from and saves to a campaign.json without
// runs (what `driftlab-cli run --machine FILE` takes). The demo fills the
// page for the simulated rig with a short procedure.

#include <QWidget>
#include <optional>

#include "core/domain/Campaign.h"

class QLabel;
class QListWidget;
class QStackedWidget;
class QVBoxLayout;

namespace driftlab::ui {

class Session;
struct RunSetup;
class ChannelSetupModel;
class ChannelTable;
class MachineForm;
class ScrewForm;
class ProcedureForm;
class RigForm;

class SetupPage : public QWidget {
    Q_OBJECT
public:
    enum Section { MachineSection, ScrewSection, ChannelsSection, ProcedureSection, RigSection };

    explicit SetupPage(Session& session, QWidget* parent = nullptr);

    /// Checks every field; marks the bad ones and shows the summary. The
    /// problems, one line each, naming the section and field.
    QStringList validate();
    /// The set-up as the fields stand, or nullopt with `problems`.
    std::optional<RunSetup> currentSetup(QStringList* problems);
    /// Validates and, when nothing is wrong, stores the set-up in the session.
    bool apply();
    /// The machine set-up (campaign without runs) as the fields stand.
    Campaign machine() const;
    void setMachine(const Campaign& campaign);
    bool loadMachine(const QString& path, QString* error);
    bool saveMachine(const QString& path, QString* error);
    /// The demo: the simulated rig's own machine and channels, two moving
    /// states shortened, speed-up 600, the demo's hidden effect, applied; a
    /// banner says what to do next.
    void loadDemo();
    bool demoBannerShown() const;
    /// The effect the demo hides in the simulated rig, a cause id of the
    /// diagnosis: what the Diagnosis page is to name after the demo's run.
    static QString demoHiddenCause();

    MachineForm* machineForm() const { return m_machine; }
    ScrewForm* screwForm() const { return m_screw; }
    ChannelSetupModel* channelModel() const { return m_channels; }
    ChannelTable* channelTable() const { return m_channelTable; }
    ProcedureForm* procedureForm() const { return m_procedure; }
    RigForm* rigForm() const { return m_rig; }
    QListWidget* sections() const { return m_sections; }

private:
    void buildButtons(QVBoxLayout* layout);
    void showTargets();
    void markSections(const QStringList& problems);
    void askMachineFile(bool save);

    Session& m_session;
    Campaign m_base;  ///< the loaded machine: keeps what the forms do not show
    QLabel* m_banner;
    QListWidget* m_sections;
    QStackedWidget* m_stack;
    MachineForm* m_machine;
    ScrewForm* m_screw;
    ChannelSetupModel* m_channels;
    ChannelTable* m_channelTable;
    ProcedureForm* m_procedure;
    RigForm* m_rig;
    QListWidget* m_problems;
    QLabel* m_status;
};

}  // namespace driftlab::ui
