#pragma once
// The Diagnosis page of the main window (DESIGN.md section 9).

#include <QWidget>

namespace driftlab::ui {

class Session;

class DiagnosisPage : public QWidget {
    Q_OBJECT
public:
    explicit DiagnosisPage(Session& session, QWidget* parent = nullptr);

private:
    Session& m_session;
};

}  // namespace driftlab::ui
