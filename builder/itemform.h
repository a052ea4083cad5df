// SPDX-License-Identifier: MIT
#pragma once

#include "componentrules.h"
#include "itemcolumn.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QUndoStack;

namespace Builder {

/**
 * A form over the fields of the current element of one part (the details below a table). Every
 * keystroke becomes an EditItemCommand (consecutive ones of a field merge), so the preview and
 * the other views follow while the user types. Problems are marked inline under each field.
 */
class ItemForm : public QWidget
{
    Q_OBJECT

public:
    /// The problems shown for the current element (default: itemProblems()).
    using Problems = std::function<FieldProblems(const Profile::RtcProfile &, int index)>;

    ItemForm(ComponentModel *model, QUndoStack *undoStack, Part part, QWidget *parent = nullptr);

    /// Adds a group title; following fields go below it.
    void addSection(const QString &title);
    /// Adds a field: a line edit, or an editable combo box when it has choices.
    QWidget *addField(const ItemField &field);
    void setProblems(Problems problems) { m_problems = std::move(problems); }
    /// Merge keys get this prefix (e.g. "interface2." for the fields of one interface).
    void setMergePrefix(const QString &prefix) { m_mergePrefix = prefix; }

    /// The element edited (position in the part's list); -1 shows an empty, disabled form.
    void setCurrentIndex(int index);
    int currentIndex() const { return m_index; }
    /// Shows the model's values again (after the caller changed what the getters read).
    void refresh();

    QWidget *editor(const QString &key) const;
    /// The problem marked under a field; empty when there is none.
    QString problem(const QString &key) const;
    /// Reloads the choices of every combo box (after the type lists changed).
    void reloadChoices();

private:
    struct Row
    {
        ItemField field;
        QWidget *editor = nullptr;
        QLabel *message = nullptr;
    };

    void followListChanges();
    void userEdited(const QString &key, const QString &text);
    void showRow(const Row &row, const PartItem *item, const FieldProblems &problems);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    Part m_part;
    Problems m_problems;
    QString m_mergePrefix;
    QString m_editingKey;
    QList<Row> m_rows;
    QFormLayout *m_form = nullptr;
    int m_index = -1;
    bool m_updating = false;
};

} // namespace Builder
