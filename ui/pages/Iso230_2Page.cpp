#include "ui/pages/Iso230_2Page.h"

#include <QLabel>
#include <QVBoxLayout>

#include "ui/app/Session.h"

namespace driftlab::ui {

Iso230_2Page::Iso230_2Page(Session& session, QWidget* parent)
    : QWidget(parent), m_session(session) {
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("(to be built)"), this));
}

}  // namespace driftlab::ui
