#pragma once
// What a push would change on the controller, asked before anything is
// written: the controller, its active table (read just before), the new
// table, the points that change and the largest change. Shown with open(),
// never exec(): the event loop (and a running test) goes on.

#include <QDialog>

#include "acquisition/push/ActiveTableRead.h"

class QDialogButtonBox;
class QPushButton;

namespace driftlab::ui {

class PushConfirmDialog : public QDialog {
    Q_OBJECT
public:
    PushConfirmDialog(const push::ActiveTable& active, const compensation::CompensationTable& next,
                      const push::TableChange& change, QWidget* parent = nullptr);

    /// The summary shown (for tests and the event log).
    QString summary() const { return m_summary; }
    /// The button that sends the table.
    QPushButton* pushButton() const { return m_push; }

private:
    QString m_summary;
    QDialogButtonBox* m_buttons;
    QPushButton* m_push;
};

}  // namespace driftlab::ui
