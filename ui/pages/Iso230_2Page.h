#pragma once
// The Iso230_2 page of the main window (DESIGN.md section 9).

#include <QWidget>

namespace driftlab::ui {

class Session;

class Iso230_2Page : public QWidget {
    Q_OBJECT
public:
    explicit Iso230_2Page(Session& session, QWidget* parent = nullptr);

private:
    Session& m_session;
};

}  // namespace driftlab::ui
