#include "ui/widgets/ChannelTable.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

#include "ui/models/ChannelSetupModel.h"
#include "ui/widgets/ChoiceDelegate.h"

namespace driftlab::ui {

ChannelTable::ChannelTable(ChannelSetupModel& model, QWidget* parent)
    : QWidget(parent), m_model(model), m_view(new QTableView(this)), m_problems(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    auto* hint = new QLabel(tr("Ids are the columns of the data and, on the Modbus rig, the "
                               "temperature module's channel ids (its device map). Models "
                               "find sensors by role."),
                            this);
    hint->setWordWrap(true);
    layout->addWidget(hint);
    m_view->setObjectName(QStringLiteral("ChannelTableView"));
    m_view->setModel(&m_model);
    m_view->setItemDelegate(new ChoiceDelegate(m_view));
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->setEditTriggers(QAbstractItemView::AllEditTriggers);
    layout->addWidget(m_view, 1);

    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add channel"), this);
    auto* remove = new QPushButton(tr("Remove selected"), this);
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_problems->setStyleSheet(QStringLiteral("color: #c02020;"));
    m_problems->setWordWrap(true);
    m_problems->hide();
    layout->addWidget(m_problems);

    connect(add, &QPushButton::clicked, this, [this] {
        const int row = m_view->currentIndex().isValid() ? m_view->currentIndex().row() + 1
                                                         : m_model.rowCount();
        m_model.insertRows(row, 1);
        m_view->setCurrentIndex(m_model.index(row, ChannelSetupModel::IdColumn));
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        std::vector<int> rows;
        for (const QModelIndex& index : m_view->selectionModel()->selectedRows())
            rows.push_back(index.row());
        std::sort(rows.rbegin(), rows.rend());  // from the bottom, so the rows do not shift
        for (int row : rows) m_model.removeRows(row, 1);
    });
}

void ChannelTable::showProblems(const QStringList& problems) {
    m_problems->setText(problems.join(QLatin1Char('\n')));
    m_problems->setVisible(!problems.isEmpty());
}

}  // namespace driftlab::ui
