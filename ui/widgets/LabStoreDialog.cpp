#include "ui/widgets/LabStoreDialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QShowEvent>
#include <QVBoxLayout>

#include "db/SpoolFile.h"
#include "db/StoreBackend.h"
#include "ui/shell/SpoolSync.h"

namespace driftlab::ui {

LabStoreDialog::LabStoreDialog(std::function<bool(const QString&)> openStore, QWidget* parent)
    : QDialog(parent),
      m_openStore(std::move(openStore)),
      m_sync(new SpoolSync(this)),
      m_url(new QLineEdit(this)),
      m_spool(new QLineEdit(this)),
      m_open(new QPushButton(tr("Open"), this)),
      m_upload(new QPushButton(tr("Upload now"), this)),
      m_state(new QLabel(this)) {
    setObjectName(QStringLiteral("LabStoreDialog"));
    setWindowTitle(tr("Open lab store"));
    m_url->setPlaceholderText(QStringLiteral("postgresql://driftlab@db1/drift"));
    m_url->setToolTip(tr("The password belongs in ~/.pgpass, not in the URL"));
    m_spool->setToolTip(
        tr("The local SQLite store a rig logs into before the server has the rows"));
    m_state->setWordWrap(true);
    m_state->setText(tr("Open a lab store to see its spool."));
    m_upload->setEnabled(false);

    auto* form = new QFormLayout;
    form->addRow(tr("Server store URL"), m_url);
    form->addRow(tr("Spool file"), m_spool);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_open, QDialogButtonBox::ActionRole);
    buttons->addButton(m_upload, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_state);
    layout->addWidget(buttons);
    resize(620, 200);

    connect(m_open, &QPushButton::clicked, this, &LabStoreDialog::openLabStore);
    connect(m_upload, &QPushButton::clicked, this, [this] {
        if (m_sync->uploadNow()) m_state->setText(tr("Uploading the spool…"));
    });
    connect(m_sync, &SpoolSync::stateChanged, this, [this](const QString& text) {
        m_state->setText(text);
        m_upload->setEnabled(true);
    });
}

void LabStoreDialog::showEvent(QShowEvent* event) {
    // Filled when first shown, not at start-up: finding the default creates its folder.
    if (m_spool->text().isEmpty()) {
        QString error;
        m_spool->setText(db::defaultSpoolPath(&error));
    }
    QDialog::showEvent(event);
}

QString LabStoreDialog::stateText() const {
    return m_state->text();
}

void LabStoreDialog::openLabStore() {
    const QString url = m_url->text().trimmed();
    if (!db::isServerStoreUrl(url)) {
        m_state->setText(tr("'%1' is not a postgresql:// URL: a lab store is named "
                            "postgresql://USER@HOST[:PORT]/DB")
                             .arg(url));
        return;
    }
    if (!m_openStore(url)) {
        m_state->setText(tr("The lab store was not opened: see the event log."));
        return;
    }
    m_upload->setEnabled(false);
    m_sync->setStores(url, m_spool->text().trimmed());
    m_sync->refresh();
    m_state->setText(tr("Reading the spool…"));
}

}  // namespace driftlab::ui
