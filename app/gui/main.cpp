// driftlab: the desktop application (docs/gui-setup.md). Wiring only: the
// window and its pages are in ui/.
//
//   driftlab [STORE]          open a store (else the last one)
//   driftlab --demo           open the demo store, set up with the simulated rig
//   driftlab --screenshots DIR   save every page as DIR/gui-<page>.png, then quit
//   driftlab --demo --autopilot  play the demo through the window: run, fit, compare,
//                                diagnose (naming the effect the demo hid), adopt
#include <glog/logging.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QMessageBox>
#include <QSettings>

#include "app/gui/DemoAutopilot.h"
#include "app/gui/ScreenshotTour.h"
#include "ui/shell/MainWindow.h"

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    // Ceres logs through glog; a fit's doubts reach the user in its notes on
    // the page, not as glog lines on the terminal (as in driftlab-cli).
    FLAGS_minloglevel = google::GLOG_FATAL;
    QApplication::setOrganizationName(QStringLiteral("DriftLab"));
    QApplication::setApplicationName(QStringLiteral("DriftLab"));
    QApplication::setApplicationVersion(QStringLiteral(DRIFTLAB_VERSION));
    // The installed desktop entry and icon (packaging/): Wayland matches the
    // window to its entry by this name, X11 takes the icon from the theme.
    QApplication::setDesktopFileName(QStringLiteral("org.driftlab.DriftLab"));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("org.driftlab.DriftLab")));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Thermal test campaigns on machine-tool feed axes."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demo{QStringLiteral("demo"),
                                  QStringLiteral("Open the demo: the simulated rig, set up.")};
    parser.addOption(demo);
    const QCommandLineOption screenshots{
        QStringLiteral("screenshots"),
        QStringLiteral("Save every page as DIR/gui-<page>.png, then quit."), QStringLiteral("DIR")};
    parser.addOption(screenshots);
    const QCommandLineOption autopilot{
        QStringLiteral("autopilot"),
        QStringLiteral("With --demo: run, fit, compare, diagnose and adopt the extension "
                       "through the window (at speed-up 0), then the screenshots if asked.")};
    parser.addOption(autopilot);
    parser.addPositionalArgument(QStringLiteral("STORE"),
                                 QStringLiteral("Campaign store to open."));
    parser.process(app);

    driftlab::ui::MainWindow window;
    window.show();
    QSettings settings;
    const bool firstStart = !settings.value(QStringLiteral("demo/offered")).toBool();
    if (parser.isSet(demo)) {
        settings.setValue(QStringLiteral("demo/offered"), true);
        window.startDemo();
    } else if (firstStart) {
        // Offered, not forced, and not modal: the window stays usable.
        settings.setValue(QStringLiteral("demo/offered"), true);
        auto* offer = new QMessageBox(
            QMessageBox::Question, QStringLiteral("Welcome to DriftLab"),
            QStringLiteral("Run the demo? A simulated feed axis with an effect hidden in it is "
                           "set up for you: press Start on the Run page, fit a model, and the "
                           "Diagnosis page names what the model misses."),
            QMessageBox::Yes | QMessageBox::No, &window);
        offer->setAttribute(Qt::WA_DeleteOnClose);
        QObject::connect(offer, &QMessageBox::buttonClicked, &window,
                         [offer, &window](QAbstractButton* button) {
                             if (offer->standardButton(button) == QMessageBox::Yes)
                                 window.startDemo();
                         });
        offer->open();
    } else if (!parser.positionalArguments().isEmpty()) {
        window.openStore(parser.positionalArguments().front(), false);
    } else if (const QString last = settings.value(QStringLiteral("stores/last")).toString();
               !last.isEmpty()) {
        window.openStore(last, false, false);
    }
    auto tour = [&window, &parser, &screenshots] {
        if (parser.isSet(screenshots))
            driftlab::gui::startScreenshotTour(window, parser.value(screenshots), 500);
    };
    if (parser.isSet(autopilot) && parser.isSet(demo))
        driftlab::gui::startDemoAutopilot(window, 0, tour);
    else
        tour();
    return app.exec();
}
