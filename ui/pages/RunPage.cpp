#include "ui/pages/RunPage.h"

#include <QAction>
#include <QLabel>
#include <QVBoxLayout>

#include "ui/app/Session.h"

namespace driftlab::ui {

RunPage::RunPage(Session& session, QWidget* parent) : QWidget(parent), m_session(session) {
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("(to be built)"), this));
    for (const char* name : {"Start", "Pause", "Resume", "Abort"}) {
        auto* action = new QAction(tr(name), this);
        action->setEnabled(false);
        m_actions << action;
    }
    m_status = new QLabel(tr("idle"), this);
}

}  // namespace driftlab::ui
