// driftlab: the desktop application (DESIGN.md section 9). Wiring only: the
// window and its pages are in ui/.
//
//   driftlab [STORE]          open a store (else the last one)
//   driftlab --demo           open the demo store, set up with the simulated rig
#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>

#include "ui/app/MainWindow.h"

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DriftLab"));
    QApplication::setApplicationName(QStringLiteral("DriftLab"));
    QApplication::setApplicationVersion(QStringLiteral(DRIFTLAB_VERSION));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Thermal test campaigns on machine-tool feed axes."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demo{QStringLiteral("demo"),
                                  QStringLiteral("Open the demo: the simulated rig, set up.")};
    parser.addOption(demo);
    parser.addPositionalArgument(QStringLiteral("STORE"),
                                 QStringLiteral("Campaign store to open."));
    parser.process(app);

    driftlab::ui::MainWindow window;
    window.show();
    QSettings settings;
    const bool firstStart = !settings.value(QStringLiteral("demo/offered")).toBool();
    if (parser.isSet(demo) || firstStart) {
        settings.setValue(QStringLiteral("demo/offered"), true);
        window.startDemo();
    } else if (!parser.positionalArguments().isEmpty()) {
        window.openStore(parser.positionalArguments().front(), false);
    } else if (const QString last = settings.value(QStringLiteral("stores/last")).toString();
               !last.isEmpty()) {
        window.openStore(last, false, false);
    }
    return app.exec();
}
