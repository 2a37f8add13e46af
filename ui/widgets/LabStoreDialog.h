#pragma once
// File → Open lab store…: the lab's shared store on a PostgreSQL server,
// named by its postgresql:// URL (docs/lab-store.md), and the spool a rig
// logs into before the server gets the rows: how many runs it holds, how
// many the server lacks, and Upload now.

#include <QDialog>
#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace driftlab::ui {

class SpoolSync;

class LabStoreDialog : public QDialog {
    Q_OBJECT
public:
    /// `openStore` opens a URL in the window (false: it said why).
    explicit LabStoreDialog(std::function<bool(const QString&)> openStore,
                            QWidget* parent = nullptr);

    QLineEdit* urlEdit() const { return m_url; }
    QLineEdit* spoolEdit() const { return m_spool; }
    QPushButton* openButton() const { return m_open; }
    QPushButton* uploadButton() const { return m_upload; }
    SpoolSync* spoolSync() const { return m_sync; }
    QString stateText() const;

protected:
    void showEvent(QShowEvent* event) override;

private:
    void openLabStore();

    std::function<bool(const QString&)> m_openStore;
    SpoolSync* m_sync;
    QLineEdit* m_url;
    QLineEdit* m_spool;
    QPushButton* m_open;
    QPushButton* m_upload;
    QLabel* m_state;
};

}  // namespace driftlab::ui
