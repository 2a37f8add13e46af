#pragma once
// `driftlab --demo --autopilot`: the demo's story played through the window
// as a user would — Start on the Run page, then Fit and Compare on the Models
// page, then Diagnose, which names the effect the demo hid in the rig, and
// Adopt its extension, then a rehearsal on the Live page — each step when the
// one before has finished; then
// `done` is called (e.g. the screenshot tour). When the diagnosis names
// another cause the application quits with status 1. For the xvfb check and
// for screenshots with data in every page.

#include <functional>

namespace driftlab::ui {
class MainWindow;
}

namespace driftlab::gui {

void startDemoAutopilot(ui::MainWindow& window, double speedup, std::function<void()> done);

}  // namespace driftlab::gui
