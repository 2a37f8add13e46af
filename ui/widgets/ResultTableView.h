#pragma once
// The read-only result tables of the pages (fit parameters, scores,
// findings, stored diagnoses): whole rows selected, one at a time, no
// editing, the last column taking the rest of the width.

#include <QAbstractItemModel>
#include <QHeaderView>
#include <QTableView>

namespace driftlab::ui {

inline QTableView* resultTableView(QAbstractItemModel* model, QWidget* parent) {
    auto* view = new QTableView(parent);
    view->setModel(model);
    view->verticalHeader()->setVisible(false);
    view->horizontalHeader()->setStretchLastSection(true);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setSelectionMode(QAbstractItemView::SingleSelection);
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->setWordWrap(false);
    return view;
}

}  // namespace driftlab::ui
