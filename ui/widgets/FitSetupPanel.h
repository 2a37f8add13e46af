#pragma once
// What to fit: the model family, the target (positioning error or a drift
// channel of spindle/ETVE runs), the training runs and the held-out test runs
// as check lists. A run is checked in one list at most.

#include <QWidget>

#include "ui/shell/FitJob.h"

class QComboBox;
class QListWidget;
class QListWidgetItem;

namespace driftlab::ui {

class FitSetupPanel : public QWidget {
    Q_OBJECT
public:
    explicit FitSetupPanel(QWidget* parent = nullptr);

    void setRunLists(const ModelledRunLists& lists);
    void clear();

    QString model() const;
    QString target() const;  ///< empty: the positioning error
    QStringList trainRuns() const;
    QStringList testRuns() const;

    QComboBox* modelBox() const { return m_model; }
    QComboBox* targetBox() const { return m_target; }
    QListWidget* trainList() const { return m_train; }
    QListWidget* testList() const { return m_test; }

signals:
    void changed();

private:
    void fillRuns();
    void keepDisjoint(QListWidgetItem* item);

    QComboBox* m_model;
    QComboBox* m_target;
    QListWidget* m_train;
    QListWidget* m_test;
    ModelledRunLists m_lists;
};

}  // namespace driftlab::ui
