#include "app/gui/DemoAutopilot.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>

#include "ui/models/LiveUpdatesModel.h"
#include "ui/pages/DiagnosisPage.h"
#include "ui/pages/LiveCompensationPage.h"
#include "ui/pages/ModelsPage.h"
#include "ui/pages/RunPage.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"
#include "ui/widgets/FitSetupPanel.h"

namespace driftlab::gui {
namespace {

/// The steps, each a condition to wait for and what to do then.
struct Step {
    std::function<bool()> ready;
    std::function<void()> act;
};

}  // namespace

void startDemoAutopilot(ui::MainWindow& window, double speedup, std::function<void()> done) {
    ui::RunSetup setup = window.session().runSetup();
    setup.speedup = speedup;
    window.session().setRunSetup(setup);
    auto* w = &window;
    auto steps = std::make_shared<std::vector<Step>>(std::vector<Step>{
        {[w] { return w->runPage()->startAction()->isEnabled(); },
         [w] {
             w->pages()->setCurrentWidget(w->runPage());
             w->runPage()->startAction()->trigger();
         }},
        {[w] {
             const auto& run = w->runPage()->controller();
             return !run.active() && run.state() == engine::EngineState::Finished &&
                    w->session().campaignId().has_value();
         },
         [w] { w->pages()->setCurrentWidget(w->modelsPage()); }},
        {[w] { return w->modelsPage()->fitButton()->isEnabled(); },
         [w] {
             // The physical model: the one the demo's cross-state matrix shows to hold.
             if (auto* model = w->modelsPage()->setupPanel()->findChild<QComboBox*>())
                 model->setCurrentIndex(model->findText(QStringLiteral("heat-transfer")));
             w->modelsPage()->fitButton()->click();
         }},
        {[w] { return !w->modelsPage()->job()->isRunning(); },
         [w] { w->modelsPage()->compareButton()->click(); }},
        {[w] { return !w->modelsPage()->job()->isRunning(); },
         [w] { w->pages()->setCurrentWidget(w->diagnosisPage()); }},
        {[w] { return w->diagnosisPage()->diagnoseButton()->isEnabled(); },
         [w] { w->diagnosisPage()->diagnoseButton()->click(); }},
        {[w] { return !w->diagnosisPage()->job()->isRunning(); },
         [w] {
             // The story: the diagnosis names what the demo hid, and its extension is kept.
             const QString verdict = w->diagnosisPage()->verdict();
             if (verdict != ui::SetupPage::demoHiddenCause()) {
                 qWarning("driftlab: the demo's diagnosis names '%s', not the hidden '%s'",
                          qPrintable(verdict), qPrintable(ui::SetupPage::demoHiddenCause()));
                 QApplication::exit(1);
                 return;
             }
             w->diagnosisPage()->adoptButton()->click();
         }},
        // Then a rehearsal of live compensation on the held-out run with the
        // adopted extension, so the Live page shows the offsets it would send.
        {[] { return true; }, [w] { w->pages()->setCurrentWidget(w->liveCompensationPage()); }},
        {[w] {
             const ui::LiveCompensationPage* live = w->liveCompensationPage();
             return live->startButton()->isEnabled() &&
                    live->modelBox()->currentText().endsWith(ui::SetupPage::demoHiddenCause());
         },
         [w] { w->liveCompensationPage()->start(); }},
        {[w] {
             const ui::LiveCompensationPage* live = w->liveCompensationPage();
             return !live->isRunning() && live->updatesModel()->rowCount() > 0;
         },
         [] {}},
    });
    auto* timer = new QTimer(&window);
    auto next = std::make_shared<std::size_t>(0);
    QObject::connect(timer, &QTimer::timeout, &window, [timer, steps, next, done] {
        if (*next < steps->size() && (*steps)[*next].ready()) (*steps)[(*next)++].act();
        if (*next == steps->size()) {
            timer->stop();
            timer->deleteLater();
            done();
        }
    });
    timer->start(200);
}

}  // namespace driftlab::gui
