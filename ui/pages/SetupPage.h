#pragma once
// The Setup page of the main window (DESIGN.md section 9).

#include <QWidget>

namespace driftlab::ui {

class Session;

class SetupPage : public QWidget {
    Q_OBJECT
public:
    explicit SetupPage(Session& session, QWidget* parent = nullptr);

private:
    Session& m_session;
};

}  // namespace driftlab::ui
