#pragma once
// The Models page of the main window (DESIGN.md section 9).

#include <QWidget>

namespace driftlab::ui {

class Session;

class ModelsPage : public QWidget {
    Q_OBJECT
public:
    explicit ModelsPage(Session& session, QWidget* parent = nullptr);

private:
    Session& m_session;
};

}  // namespace driftlab::ui
