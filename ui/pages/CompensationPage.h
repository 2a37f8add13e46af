#pragma once
// The Compensation page of the main window (DESIGN.md section 9).

#include <QWidget>

namespace driftlab::ui {

class Session;

class CompensationPage : public QWidget {
    Q_OBJECT
public:
    explicit CompensationPage(Session& session, QWidget* parent = nullptr);

private:
    Session& m_session;
};

}  // namespace driftlab::ui
