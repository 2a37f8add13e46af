#include "ui/widgets/FieldErrors.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>

namespace driftlab::ui {

void FieldErrors::addRow(QFormLayout* form, const QString& label, QWidget* editor) {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* error = new QLabel(row);
    error->setStyleSheet(QStringLiteral("color: #c02020;"));
    error->setWordWrap(true);
    error->hide();
    layout->addWidget(editor);
    layout->addWidget(error, 1);
    form->addRow(label, row);
    m_labels.insert(editor, error);
}

void FieldErrors::clear() {
    for (QLabel* label : std::as_const(m_labels)) {
        label->clear();
        label->hide();
    }
}

void FieldErrors::fail(QWidget* editor, const QString& where, const QString& why,
                       QStringList& summary) {
    if (QLabel* label = m_labels.value(editor)) {
        label->setText(why);
        label->show();
    }
    summary << where + QStringLiteral(": ") + why;
}

QString FieldErrors::errorOf(const QWidget* editor) const {
    const QLabel* label = m_labels.value(editor);
    return label ? label->text() : QString();
}

}  // namespace driftlab::ui
