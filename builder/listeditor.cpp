// SPDX-License-Identifier: MIT
#include "listeditor.h"

#include "itemcommands.h"
#include "itemtablemodel.h"

#include <QComboBox>
#include <QCompleter>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

/// Cells of a field with choices are edited with a combo box (editable when the choices are
/// suggestions), like the form beside the table.
class ChoiceDelegate : public QStyledItemDelegate
{
public:
    ChoiceDelegate(ItemTableModel *table, QObject *parent)
        : QStyledItemDelegate(parent)
        , m_table(table)
    { }

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override
    {
        const ItemField &field = m_table->column(index.column());
        if (!field.choices)
            return QStyledItemDelegate::createEditor(parent, option, index);
        auto *combo = new QComboBox(parent);
        combo->setEditable(field.editableChoices);
        combo->setInsertPolicy(QComboBox::NoInsert);
        combo->addItems(field.choices());
        if (field.editableChoices)
            combo->completer()->setFilterMode(Qt::MatchContains);
        return combo;
    }

    void setEditorData(QWidget *editor, const QModelIndex &index) const override
    {
        auto *combo = qobject_cast<QComboBox *>(editor);
        if (!combo)
            return QStyledItemDelegate::setEditorData(editor, index);
        const QString value = index.data(Qt::EditRole).toString();
        const int found = combo->findText(value);
        if (found >= 0)
            combo->setCurrentIndex(found);
        else if (combo->isEditable())
            combo->setEditText(value);
    }

    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override
    {
        if (auto *combo = qobject_cast<QComboBox *>(editor))
            model->setData(index, combo->currentText(), Qt::EditRole);
        else
            QStyledItemDelegate::setModelData(editor, model, index);
    }

private:
    ItemTableModel *m_table;
};

} // namespace

ListEditor::ListEditor(ComponentModel *model, QUndoStack *undoStack, ItemTableModel *table,
                       const QString &title, Factory factory, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_table(table)
    , m_factory(std::move(factory))
    , m_view(new QTableView(this))
    , m_remove(new QPushButton(tr("Remove"), this))
    , m_up(new QPushButton(tr("Up"), this))
    , m_down(new QPushButton(tr("Down"), this))
{
    table->setParent(this);
    m_view->setModel(table);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setItemDelegate(new ChoiceDelegate(table, m_view));
    m_view->horizontalHeader()->setStretchLastSection(true);
    if (table->columnCount() <= 4)
        m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 8);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed);

    auto *add = new QPushButton(tr("Add"), this);
    connect(add, &QPushButton::clicked, this, &ListEditor::addItem);
    connect(m_remove, &QPushButton::clicked, this, &ListEditor::removeCurrent);
    connect(m_up, &QPushButton::clicked, this, [this] { moveCurrent(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { moveCurrent(1); });
    add->setObjectName(QStringLiteral("add"));
    m_remove->setObjectName(QStringLiteral("remove"));

    auto *buttons = new QVBoxLayout;
    for (QPushButton *button : {add, m_remove, m_up, m_down})
        buttons->addWidget(button);
    buttons->addStretch(1);
    auto *row = new QHBoxLayout;
    row->addWidget(m_view, 1);
    row->addLayout(buttons);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *heading = new QLabel(QStringLiteral("<b>%1</b>").arg(title.toHtmlEscaped()), this);
    layout->addWidget(heading);
    layout->addLayout(row);

    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this] {
        updateButtons();
        emit currentItemChanged(currentItem());
    });
    // Row changes move the current index without a currentRowChanged for the element itself.
    const auto rowsChanged = [this] {
        updateButtons();
        emit currentItemChanged(currentItem());
    };
    connect(table, &QAbstractItemModel::rowsInserted, this, rowsChanged);
    connect(table, &QAbstractItemModel::rowsRemoved, this, rowsChanged);
    connect(table, &QAbstractItemModel::modelReset, this, rowsChanged);
    updateButtons();
}

int ListEditor::currentItem() const
{
    const QModelIndex current = m_view->currentIndex();
    return current.isValid() ? m_table->itemIndex(current.row()) : -1;
}

void ListEditor::selectItem(int itemIndex)
{
    const int row = m_table->rowOf(itemIndex);
    if (row >= 0)
        m_view->setCurrentIndex(m_table->index(row, 0));
}

void ListEditor::addItem()
{
    // New elements go after the last one shown in this table (InPorts stay together).
    const int rows = m_table->rowCount();
    const int at
        = rows > 0 ? m_table->itemIndex(rows - 1) + 1 : m_model->itemCount(m_table->part());
    m_undoStack->push(new InsertItemCommand(m_model, m_table->part(), at, m_factory()));
    selectItem(at);
}

void ListEditor::removeCurrent()
{
    const int item = currentItem();
    if (item >= 0)
        m_undoStack->push(new RemoveItemCommand(m_model, m_table->part(), item));
}

void ListEditor::moveCurrent(int delta)
{
    const QModelIndex current = m_view->currentIndex();
    const int row = current.row() + delta;
    if (!current.isValid() || row < 0 || row >= m_table->rowCount())
        return;
    // Swap with the neighbour shown in this table, which may not be the neighbour in the list.
    const int from = m_table->itemIndex(current.row());
    const int to = m_table->itemIndex(row);
    m_undoStack->push(new MoveItemCommand(m_model, m_table->part(), from, to));
    selectItem(to);
}

void ListEditor::updateButtons()
{
    const QModelIndex current = m_view->currentIndex();
    m_remove->setEnabled(current.isValid());
    m_up->setEnabled(current.isValid() && current.row() > 0);
    m_down->setEnabled(current.isValid() && current.row() + 1 < m_table->rowCount());
}

QString uniqueName(const QString &base, const QStringList &used)
{
    if (!used.contains(base))
        return base;
    for (int i = 1;; ++i) {
        const QString name = base + QString::number(i);
        if (!used.contains(name))
            return name;
    }
}

QStringList portNames(const Profile::RtcProfile &profile)
{
    QStringList names;
    for (const auto &port : profile.dataPorts)
        names << port.name;
    for (const auto &port : profile.servicePorts)
        names << port.name;
    return names;
}

} // namespace Builder
