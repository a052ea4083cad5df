// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QPlainTextEdit;
class QUndoStack;

namespace Builder {

/**
 * The Builder's "Documentation" page: the component's description, input/output, algorithm,
 * reference, creator/contact (`name <mail>`) and license. Typing in a field is one undo step.
 */
class DocumentationPage : public QWidget
{
    Q_OBJECT

public:
    enum class Field { Description, InOut, Algorithm, Reference, Creator, License };

    DocumentationPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    QPlainTextEdit *editor(Field field) const;

private:
    void refresh();
    void userEdited(Field field);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    QList<QPlainTextEdit *> m_editors;
    bool m_updating = false;
};

} // namespace Builder
