// SPDX-License-Identifier: MIT
#include "activitypage.h"

#include "actiontablemodel.h"
#include "componentcommands.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QTableView>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

using DocMember = std::optional<QString> Profile::RtcActionDoc::*;

DocMember member(ActivityPage::DocField field)
{
    switch (field) {
    case ActivityPage::DocField::Description:
        return &Profile::RtcActionDoc::description;
    case ActivityPage::DocField::PreCondition:
        return &Profile::RtcActionDoc::preCondition;
    case ActivityPage::DocField::PostCondition:
        break;
    }
    return &Profile::RtcActionDoc::postCondition;
}

const char *mergeKey(ActivityPage::DocField field)
{
    switch (field) {
    case ActivityPage::DocField::Description:
        return "description";
    case ActivityPage::DocField::PreCondition:
        return "preCondition";
    case ActivityPage::DocField::PostCondition:
        break;
    }
    return "postCondition";
}

} // namespace

ActivityPage::ActivityPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_table(new ActionTableModel(model, undoStack, this))
    , m_view(new QTableView(this))
{
    m_view->setModel(m_table);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->verticalHeader()->hide();
    m_view->resizeColumnToContents(ActionTableModel::CallbackColumn);
    m_view->setColumnWidth(ActionTableModel::CallbackColumn,
                           m_view->columnWidth(ActionTableModel::CallbackColumn) + 40);

    auto *group = new QGroupBox(this);
    m_group = group;
    auto *form = new QFormLayout(group);
    const QList<QPair<DocField, QString>> fields {
        {DocField::Description, tr("&Description:")},
        {DocField::PreCondition, tr("&Precondition:")},
        {DocField::PostCondition, tr("P&ostcondition:")},
    };
    for (const auto &[field, label] : fields) {
        auto *edit = new QLineEdit(group);
        connect(edit, &QLineEdit::textEdited, this,
                [this, field = field](const QString &text) { userEdited(field, text); });
        form->addRow(label, edit);
        m_docEditors << edit;
    }
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    layout->addWidget(group);

    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                m_row = current.isValid() ? current.row() : 0;
                refreshForm();
            });
    connect(model, &ComponentModel::actionChanged, this, &ActivityPage::refreshForm);
    connect(model, &ComponentModel::profileReset, this, &ActivityPage::refreshForm);
    selectRow(0);
}

QLineEdit *ActivityPage::docEditor(DocField field) const
{
    return m_docEditors.at(int(field));
}

void ActivityPage::selectRow(int row)
{
    m_view->setCurrentIndex(m_table->index(row, ActionTableModel::CallbackColumn));
    m_row = row;
    refreshForm();
}

void ActivityPage::refreshForm()
{
    if (!m_model)
        return;
    const Profile::RtcAction action = ActionTableModel::action(m_row);
    m_group->setTitle(tr("Callback %1").arg(Profile::rtcActionKey(action)));
    const auto status = m_model->action(action);
    for (DocField field :
         {DocField::Description, DocField::PreCondition, DocField::PostCondition}) {
        const QString text = status && status->doc
            ? ((*status->doc).*member(field)).value_or(QString())
            : QString();
        QLineEdit *edit = docEditor(field);
        if (edit->text() != text)
            edit->setText(text);
    }
}

void ActivityPage::userEdited(DocField field, const QString &text)
{
    const Profile::RtcAction action = ActionTableModel::action(m_row);
    const auto status = m_model->action(action);
    Profile::RtcActionStatus edited = status.value_or(Profile::RtcActionStatus());
    if (!edited.doc)
        edited.doc = Profile::RtcActionDoc();
    (*edited.doc).*member(field) = text;
    if (edited == status)
        return;
    m_undoStack->push(
        new SetActionCommand(m_model, action, edited, QLatin1String(mergeKey(field))));
}

} // namespace Builder
