#pragma once
// `driftlab --screenshots DIR`: shows every page of the main window in turn
// and saves it as DIR/gui-<page>.png (the whole window), then quits. Used
// under a real X server (xvfb-run) to look at the GUI as a user sees it.

#include <QObject>
#include <QString>

namespace driftlab::ui {
class MainWindow;
}

namespace driftlab::gui {

/// Starts the tour after `delay_ms` (time for the window to settle or a demo
/// to fill it); quits the application with 0 when every page is saved, 1 when
/// a file could not be written.
void startScreenshotTour(ui::MainWindow& window, const QString& dir, int delay_ms);

}  // namespace driftlab::gui
