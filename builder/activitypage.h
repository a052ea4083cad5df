// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QGroupBox;
class QLineEdit;
class QTableView;
class QUndoStack;

namespace Builder {

class ActionTableModel;

/**
 * The Builder's "Activity" page: the callbacks ON/OFF with their description and, for the
 * selected one, its description, precondition and postcondition.
 */
class ActivityPage : public QWidget
{
    Q_OBJECT

public:
    enum class DocField { Description, PreCondition, PostCondition };

    ActivityPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    QTableView *view() const { return m_view; }
    ActionTableModel *table() const { return m_table; }
    QLineEdit *docEditor(DocField field) const;
    /// Shows the callback of a row in the form below the table.
    void selectRow(int row);

private:
    void refreshForm();
    void userEdited(DocField field, const QString &text);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    ActionTableModel *m_table;
    QTableView *m_view;
    QList<QLineEdit *> m_docEditors;
    QGroupBox *m_group = nullptr;
    int m_row = 0;
};

} // namespace Builder
