#pragma once
// A combo-box editor for cells whose model offers choices (a QStringList in
// ChannelSetupModel::ChoicesRole); other cells get the default editor.

#include <QStyledItemDelegate>

namespace driftlab::ui {

class ChoiceDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;
    void setEditorData(QWidget* editor, const QModelIndex& index) const override;
    void setModelData(QWidget* editor, QAbstractItemModel* model,
                      const QModelIndex& index) const override;
};

}  // namespace driftlab::ui
