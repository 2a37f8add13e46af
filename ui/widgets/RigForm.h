#pragma once
// Set-up section "Rig": the simulated rig (seed, speed-up, hidden effects) or
// the Modbus rig (temperature module URL and its device map, controller and
// interferometer URLs). The device addresses persist with QSettings.

#include <QWidget>
#include <optional>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "ui/widgets/FieldErrors.h"

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace driftlab::ui {

struct RunSetup;

class RigForm : public QWidget {
    Q_OBJECT
public:
    explicit RigForm(QWidget* parent = nullptr);

    bool isSimulated() const;
    void setSimulated(bool simulated);
    /// The device map of the Modbus rig as read from its file (nullopt when
    /// the simulated rig is chosen or the file does not read).
    const std::optional<devices::ChannelRegisterMap>& deviceMap() const { return m_deviceMap; }
    /// Writes the rig options into `setup`.
    void applyTo(RunSetup& setup) const;
    /// Fills the fields from `setup`.
    void setFrom(const RunSetup& setup);
    /// Marks bad fields and appends "Rig → …" lines to `summary`.
    void validate(QStringList& summary);
    const FieldErrors& errors() const { return m_errors; }

    void loadSettings();
    void saveSettings() const;

    QComboBox* kind;
    QSpinBox* seed;
    QDoubleSpinBox* speedup;
    QLineEdit* effects;  ///< ID=VALUE, comma separated
    QLineEdit* temperatureUrl;
    QLineEdit* deviceMapPath;
    QLineEdit* controllerUrl;
    QLineEdit* interferometerUrl;

signals:
    /// The rig kind or the device map changed (the channel table shows it).
    void rigChanged();
    void speedupChanged(double speedup);

private:
    void readDeviceMap();

    QStackedWidget* m_stack;
    FieldErrors m_errors;
    std::optional<devices::ChannelRegisterMap> m_deviceMap;
    QString m_deviceMapError;
};

}  // namespace driftlab::ui
