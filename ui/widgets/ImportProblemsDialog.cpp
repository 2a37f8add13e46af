#include "ui/widgets/ImportProblemsDialog.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include "ui/models/ImportProblemsModel.h"

namespace driftlab::ui {

ImportProblemsDialog::ImportProblemsDialog(QWidget* parent)
    : QDialog(parent),
      m_model(new ImportProblemsModel(this)),
      m_summary(new QLabel(this)),
      m_view(new QTableView(this)) {
    setObjectName(QStringLiteral("ImportProblemsDialog"));
    setWindowTitle(tr("Campaign not imported"));
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::RichText);
    m_view->setModel(m_model);
    m_view->setObjectName(QStringLiteral("ImportProblems"));
    m_view->verticalHeader()->hide();
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setWordWrap(true);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setSectionResizeMode(ImportProblemsModel::Message,
                                                     QHeaderView::Stretch);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_view, 1);
    layout->addWidget(buttons);
    resize(820, 240);
}

void ImportProblemsDialog::showProblems(const QString& source, const QString& store,
                                        const QStringList& errors, const QStringList& warnings) {
    m_model->setProblems(errors, warnings, source);
    m_summary->setText(
        tr("<b>%1</b> was not imported: nothing was stored in %2. Fix the file where the "
           "list below says, then import it again.")
            .arg(QFileInfo(source).fileName().toHtmlEscaped(), store.toHtmlEscaped()));
    m_view->resizeRowsToContents();
    m_view->setCurrentIndex({});
    open();  // window-modal, not exec(): the window's event loop goes on
}

QString ImportProblemsDialog::summary() const {
    return m_summary->text();
}

}  // namespace driftlab::ui
