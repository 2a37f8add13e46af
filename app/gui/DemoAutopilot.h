#pragma once
// `driftlab --demo --autopilot`: the demo played through the window as a
// user would — Start on the Run page, then Fit on the Models page, then
// Diagnose — each step when the one before has finished; then `done` is
// called (e.g. the screenshot tour). For the xvfb check and for screenshots
// with data in every page.

#include <functional>

namespace driftlab::ui {
class MainWindow;
}

namespace driftlab::gui {

void startDemoAutopilot(ui::MainWindow& window, double speedup, std::function<void()> done);

}  // namespace driftlab::gui
