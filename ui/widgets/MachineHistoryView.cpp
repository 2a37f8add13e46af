#include "ui/widgets/MachineHistoryView.h"

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "db/MachineHistoryStore.h"
#include "ui/models/MachineHistoryModel.h"
#include "ui/plots/HistoryPlot.h"
#include "ui/widgets/PlotView.h"

namespace driftlab::ui {

MachineHistoryView::MachineHistoryView(QWidget* parent)
    : QWidget(parent),
      m_message(new QLabel(this)),
      m_view(new QTableView(this)),
      m_model(new MachineHistoryModel(this)),
      m_plot(new PlotView(this)) {
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_view->setModel(m_model);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_view);
    split->addWidget(m_plot);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_message);
    layout->addWidget(split, 1);
    connect(&m_watcher, &QFutureWatcher<Result>::finished, this,
            [this] { show(m_watcher.result()); });
    clear();
}

MachineHistoryView::~MachineHistoryView() {
    m_watcher.waitForFinished();
}

void MachineHistoryView::clear() {
    m_model->setHistory({});
    m_plot->showMessage(tr("Select a stored campaign to see its machine axis over its campaigns."));
    m_message->clear();
}

void MachineHistoryView::load(const QString& storePath, const QString& machine,
                              const QString& axis) {
    m_message->setText(tr("loading the history of %1 axis %2…").arg(machine, axis));
    // A connection belongs to the thread that opened it: the worker opens its own.
    m_watcher.setFuture(QtConcurrent::run([storePath, machine, axis] {
        Result result;
        auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, &result.error);
        if (store) result.history = db::machineHistory(*store, machine, axis, {}, &result.error);
        return result;
    }));
}

void MachineHistoryView::show(const Result& result) {
    if (!result.history) {
        m_model->setHistory({});
        m_plot->showMessage(result.error);
        m_message->setText(result.error);
        return emit loaded();
    }
    const history::MachineHistory& h = *result.history;
    m_message->setText(tr("%1 campaign(s) of %2 axis %3, oldest first, by the date campaign.json "
                          "records, else the import time (docs/history.md); %4, k = %5")
                           .arg(h.entries.size())
                           .arg(h.machine, h.axis, iso::toString(h.settings.iso.edition))
                           .arg(h.settings.iso.coverage_factor));
    m_model->setHistory(h);
    m_plot->showCurves(historyTrendPlot(h));
    emit loaded();
}

}  // namespace driftlab::ui
