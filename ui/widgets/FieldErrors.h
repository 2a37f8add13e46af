#pragma once
// Inline validation messages of a form: each checked editor gets a red label
// beside it, empty while the field is fine. A failed check shows the reason
// there and adds "Section → field: reason" to the page's summary, so the
// user sees both where and what.

#include <QHash>
#include <QString>
#include <QStringList>

class QFormLayout;
class QLabel;
class QWidget;

namespace driftlab::ui {

class FieldErrors {
public:
    /// Adds `editor` as a row of `form` under `label`, with its error label.
    void addRow(QFormLayout* form, const QString& label, QWidget* editor);
    /// Hides every message.
    void clear();
    /// Shows `why` beside `editor` and appends "`where`: `why`" to `summary`.
    void fail(QWidget* editor, const QString& where, const QString& why, QStringList& summary);
    /// The message shown beside `editor` (empty when none).
    QString errorOf(const QWidget* editor) const;

private:
    QHash<const QWidget*, QLabel*> m_labels;
};

}  // namespace driftlab::ui
