#include "ui/widgets/PushConfirmDialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace driftlab::ui {

PushConfirmDialog::PushConfirmDialog(const push::ActiveTable& active,
                                     const compensation::CompensationTable& next,
                                     const push::TableChange& change, QWidget* parent)
    : QDialog(parent), m_buttons(new QDialogButtonBox(this)) {
    setWindowTitle(tr("Push the compensation table?"));
    setAttribute(Qt::WA_DeleteOnClose);
    const QString now = active.empty() ? tr("no table")
                                       : tr("table v%1, %2 points from %3 mm every %4 mm")
                                             .arg(active.image.version())
                                             .arg(active.image.points())
                                             .arg(active.image.start_um() / 1000.0, 0, 'f', 3)
                                             .arg(active.image.spacing_um() / 1000.0, 0, 'f', 3);
    m_summary =
        tr("Controller %1 (machine %2) holds %3.\n"
           "New table: %4 points from %5 to %6 mm, %7.\n"
           "%8 of %4 points change; the largest change is %9 µm at %10 mm.\n"
           "The controller applies the table when the machine is not cutting, reads it back, and "
           "rolls back to the table it holds now on any mismatch.")
            .arg(active.controller, machineStateName(active.state), now)
            .arg(next.size())
            .arg(next.position_mm.front(), 0, 'f', 3)
            .arg(next.position_mm.back(), 0, 'f', 3)
            .arg(next.bidirectional ? tr("bidirectional") : tr("unidirectional"))
            .arg(change.points_changed)
            .arg(change.largest_change_um, 0, 'f', 3)
            .arg(change.largest_at_mm, 0, 'f', 3);
    auto* text = new QLabel(m_summary, this);
    text->setWordWrap(true);
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_push = m_buttons->addButton(tr("Push"), QDialogButtonBox::AcceptRole);
    m_buttons->addButton(QDialogButtonBox::Cancel);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text);
    layout->addWidget(m_buttons);
    resize(520, sizeHint().height());
}

}  // namespace driftlab::ui
