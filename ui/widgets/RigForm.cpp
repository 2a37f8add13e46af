#include "ui/widgets/RigForm.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QUrl>
#include <QVBoxLayout>

#include "acquisition/modbus/ModbusUrl.h"
#include "core/rig/RigEffects.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {
namespace {
const QString kShippedDeviceMap = QStringLiteral(":/devices/temperature-8ch-pt100.json");

QStringList effectList(const QString& text) {
    QStringList out;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!part.trimmed().isEmpty()) out << part.trimmed();
    return out;
}
}  // namespace

RigForm::RigForm(QWidget* parent)
    : QWidget(parent),
      kind(new QComboBox(this)),
      seed(new QSpinBox(this)),
      speedup(new QDoubleSpinBox(this)),
      effects(new QLineEdit(this)),
      temperatureUrl(new QLineEdit(this)),
      deviceMapPath(new QLineEdit(this)),
      controllerUrl(new QLineEdit(this)),
      interferometerUrl(new QLineEdit(this)),
      m_stack(new QStackedWidget(this)) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    kind->addItem(tr("Simulated rig (runs on this computer)"), QStringLiteral("sim"));
    kind->addItem(tr("Modbus rig (temperature module, controller, interferometer)"),
                  QStringLiteral("modbus"));
    top->addRow(tr("Rig"), kind);
    layout->addLayout(top);

    auto* sim = new QGroupBox(tr("Simulated rig"), this);
    auto* simForm = new QFormLayout(sim);
    seed->setRange(0, std::numeric_limits<int>::max());
    speedup->setRange(0, 1e6);
    speedup->setDecimals(0);
    speedup->setSuffix(QStringLiteral(" ×"));
    effects->setPlaceholderText(tr("e.g. nut_heat_exponent=1.4, forced_convection_h1=0.5"));
    m_errors.addRow(simForm, tr("Seed (noise, room)"), seed);
    m_errors.addRow(simForm, tr("Speed-up (simulated s per s)"), speedup);
    m_errors.addRow(simForm, tr("Hidden effects (ID=VALUE, …)"), effects);
    m_stack->addWidget(sim);

    auto* modbus = new QGroupBox(tr("Modbus rig"), this);
    auto* modbusForm = new QFormLayout(modbus);
    temperatureUrl->setPlaceholderText(
        tr("modbus://192.168.0.10:502 or modbus-rtu:///dev/ttyUSB0"));
    controllerUrl->setPlaceholderText(tr("modbus://HOST:PORT (empty: no controller link)"));
    interferometerUrl->setPlaceholderText(tr("tcp://HOST:PORT (empty: no interferometer)"));
    auto* mapRow = new QWidget(modbus);
    auto* mapLayout = new QHBoxLayout(mapRow);
    mapLayout->setContentsMargins(0, 0, 0, 0);
    mapLayout->addWidget(deviceMapPath, 1);
    auto* browse = new QPushButton(tr("Browse…"), mapRow);
    mapLayout->addWidget(browse);
    m_errors.addRow(modbusForm, tr("Temperature module URL"), temperatureUrl);
    m_errors.addRow(modbusForm, tr("Device map file"), mapRow);
    m_errors.addRow(modbusForm, tr("Controller URL"), controllerUrl);
    m_errors.addRow(modbusForm, tr("Interferometer URL"), interferometerUrl);
    m_stack->addWidget(modbus);
    layout->addWidget(m_stack);
    layout->addStretch(1);

    connect(kind, &QComboBox::currentIndexChanged, this, [this](int index) {
        m_stack->setCurrentIndex(index);
        readDeviceMap();
    });
    connect(speedup, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { emit speedupChanged(isSimulated() ? v : 0); });
    connect(deviceMapPath, &QLineEdit::editingFinished, this, &RigForm::readDeviceMap);
    connect(browse, &QPushButton::clicked, this, [this] {
        auto* dialog =
            new QFileDialog(this, tr("Device map of the temperature module"),
                            QFileInfo(deviceMapPath->text()).path(), tr("Device maps (*.json)"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setFileMode(QFileDialog::ExistingFile);
        connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
            deviceMapPath->setText(path);
            readDeviceMap();
        });
        dialog->open();
    });
    speedup->setValue(600);
    deviceMapPath->setText(kShippedDeviceMap);
}

bool RigForm::isSimulated() const {
    return kind->currentData().toString() == QLatin1String("sim");
}

void RigForm::setSimulated(bool simulated) {
    kind->setCurrentIndex(simulated ? 0 : 1);
}

void RigForm::readDeviceMap() {
    m_deviceMap.reset();
    m_deviceMapError.clear();
    if (!isSimulated()) {
        m_deviceMap = devices::loadChannelRegisterMap(deviceMapPath->text(), &m_deviceMapError);
    }
    emit rigChanged();
    emit speedupChanged(isSimulated() ? speedup->value() : 0);
}

void RigForm::applyTo(RunSetup& setup) const {
    setup.rig = kind->currentData().toString();
    setup.seed = unsigned(seed->value());
    setup.speedup = speedup->value();
    setup.effects = effectList(effects->text());
    setup.temperature_url = temperatureUrl->text().trimmed();
    setup.device_map_path = deviceMapPath->text().trimmed();
    setup.controller_url = controllerUrl->text().trimmed();
    setup.interferometer_url = interferometerUrl->text().trimmed();
}

void RigForm::setFrom(const RunSetup& setup) {
    seed->setValue(int(std::min<unsigned>(setup.seed, std::numeric_limits<int>::max())));
    speedup->setValue(setup.speedup);
    effects->setText(setup.effects.join(QStringLiteral(", ")));
    temperatureUrl->setText(setup.temperature_url);
    if (!setup.device_map_path.isEmpty()) deviceMapPath->setText(setup.device_map_path);
    controllerUrl->setText(setup.controller_url);
    interferometerUrl->setText(setup.interferometer_url);
    setSimulated(setup.rig != QLatin1String("modbus"));
    readDeviceMap();
}

void RigForm::validate(QStringList& summary) {
    m_errors.clear();
    QString error;
    if (isSimulated()) {
        if (speedup->value() <= 0)
            m_errors.fail(speedup, tr("Rig → speed-up"), tr("must be > 0"), summary);
        rig::RigEffects hidden;
        for (const QString& assignment : effectList(effects->text()))
            if (!rig::applyEffect(hidden, assignment, &error))
                m_errors.fail(effects, tr("Rig → effects"), error, summary);
        return;
    }
    if (!modbus::parseModbusUrl(temperatureUrl->text().trimmed(), &error))
        m_errors.fail(temperatureUrl, tr("Rig → temperature module URL"), error, summary);
    if (!m_deviceMap)
        m_errors.fail(deviceMapPath->parentWidget(), tr("Rig → device map"),
                      m_deviceMapError.isEmpty() ? tr("not read") : m_deviceMapError, summary);
    const QString controller = controllerUrl->text().trimmed();
    if (!controller.isEmpty() && !modbus::parseModbusUrl(controller, &error))
        m_errors.fail(controllerUrl, tr("Rig → controller URL"), error, summary);
    const QString ifm = interferometerUrl->text().trimmed();
    const QUrl url(ifm, QUrl::StrictMode);
    if (!ifm.isEmpty() && (!url.isValid() || url.scheme() != QLatin1String("tcp") ||
                           url.host().isEmpty() || url.port() <= 0))
        m_errors.fail(interferometerUrl, tr("Rig → interferometer URL"),
                      tr("'%1' is not tcp://HOST:PORT").arg(ifm), summary);
}

void RigForm::loadSettings() {
    QSettings s;
    s.beginGroup(QStringLiteral("setup/devices"));
    temperatureUrl->setText(s.value(QStringLiteral("temperature_url")).toString());
    deviceMapPath->setText(s.value(QStringLiteral("device_map"), kShippedDeviceMap).toString());
    controllerUrl->setText(s.value(QStringLiteral("controller_url")).toString());
    interferometerUrl->setText(s.value(QStringLiteral("interferometer_url")).toString());
    s.endGroup();
    readDeviceMap();
}

void RigForm::saveSettings() const {
    QSettings s;
    s.beginGroup(QStringLiteral("setup/devices"));
    s.setValue(QStringLiteral("temperature_url"), temperatureUrl->text().trimmed());
    s.setValue(QStringLiteral("device_map"), deviceMapPath->text().trimmed());
    s.setValue(QStringLiteral("controller_url"), controllerUrl->text().trimmed());
    s.setValue(QStringLiteral("interferometer_url"), interferometerUrl->text().trimmed());
    s.endGroup();
}

}  // namespace driftlab::ui
