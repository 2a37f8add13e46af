#include "ui/widgets/FitSetupPanel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QSignalBlocker>

#include "core/models/ModelFactory.h"

namespace driftlab::ui {
namespace {

QStringList checked(const QListWidget* list) {
    QStringList ids;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->checkState() == Qt::Checked) ids << list->item(i)->text();
    return ids;
}

}  // namespace

FitSetupPanel::FitSetupPanel(QWidget* parent) : QWidget(parent) {
    m_model = new QComboBox(this);
    for (const QString& name : models::fitModelNames()) {
        m_model->addItem(name, name);
        m_model->setItemData(m_model->count() - 1, models::makeModel(name)->describe(),
                             Qt::ToolTipRole);
    }
    m_target = new QComboBox(this);
    m_train = new QListWidget(this);
    m_test = new QListWidget(this);
    for (QListWidget* list : {m_train, m_test}) {
        list->setMaximumHeight(120);
        connect(list, &QListWidget::itemChanged, this, &FitSetupPanel::keepDisjoint);
    }
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Model"), m_model);
    form->addRow(tr("Target"), m_target);
    form->addRow(tr("Training runs"), m_train);
    form->addRow(tr("Test runs (held out)"), m_test);
    connect(m_model, &QComboBox::currentIndexChanged, this, &FitSetupPanel::changed);
    connect(m_target, &QComboBox::currentIndexChanged, this, [this] {
        fillRuns();
        emit changed();
    });
}

void FitSetupPanel::setRunLists(const ModelledRunLists& lists) {
    m_lists = lists;
    const QSignalBlocker blocker(m_target);
    m_target->clear();
    for (const QString& target : lists.targets)
        m_target->addItem(target.isEmpty() ? tr("positioning error") : tr("drift: %1").arg(target),
                          target);
    fillRuns();
    emit changed();
}

void FitSetupPanel::clear() {
    setRunLists({});
}

void FitSetupPanel::fillRuns() {
    const QSignalBlocker trainBlocker(m_train), testBlocker(m_test);
    m_train->clear();
    m_test->clear();
    const auto found = m_lists.runs.find(target());
    if (found == m_lists.runs.end()) return;
    // As `driftlab-cli fit` without --train/--test: the first run trains, the others test.
    bool first = true;
    for (const QString& run : found->second) {
        auto* train = new QListWidgetItem(run, m_train);
        train->setCheckState(first ? Qt::Checked : Qt::Unchecked);
        auto* test = new QListWidgetItem(run, m_test);
        test->setCheckState(first ? Qt::Unchecked : Qt::Checked);
        first = false;
    }
}

void FitSetupPanel::keepDisjoint(QListWidgetItem* item) {
    // A run checked for training leaves the test list and the other way round:
    // a held-out score must come from runs the fit has not seen.
    if (item->checkState() == Qt::Checked) {
        QListWidget* other = item->listWidget() == m_train ? m_test : m_train;
        const QSignalBlocker blocker(other);
        for (auto* twin : other->findItems(item->text(), Qt::MatchExactly))
            twin->setCheckState(Qt::Unchecked);
    }
    emit changed();
}

QString FitSetupPanel::model() const {
    return m_model->currentData().toString();
}

QString FitSetupPanel::target() const {
    return m_target->currentData().toString();
}

QStringList FitSetupPanel::trainRuns() const {
    return checked(m_train);
}

QStringList FitSetupPanel::testRuns() const {
    return checked(m_test);
}

}  // namespace driftlab::ui
