// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "diagnostic.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QUndoStack;

namespace Builder {

/**
 * The Builder's "Basic" page: name, description, version, vendor, category, component and
 * activity type, max instances, execution type and rate of a component, and the button row
 * that starts code generation.
 *
 * Every change the user makes is pushed as a SetBasicFieldCommand onto the undo stack; the page
 * itself only shows what the model says (it refreshes on the model's signals, including after
 * undo). Problems (e.g. a character the name rule forbids) are marked inline under the field.
 */
class BasicPage : public QWidget
{
    Q_OBJECT

public:
    BasicPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    /// The editor of a field: a QLineEdit, or a QComboBox for the choice fields.
    QWidget *editor(BasicField field) const;
    /// The problem marked under a field; empty when there is none.
    QString problem(BasicField field) const;

    /// RTC Builder's preset categories.
    static QStringList categoryPresets();
    /// The execution contexts offered for execution type.
    static QStringList executionTypePresets();

    QPushButton *generateButton() const { return m_generate; }
    /// Lists what keeps Generate from running (empty: hides the list).
    void showGenerationProblems(const Profile::Diagnostics &problems);
    /// The text of that list; empty when hidden.
    QString generationProblems() const;

signals:
    /// The user asked to generate code (the Generate button).
    void generateRequested();
    /// The user asked to restore generated code from a backup (Code restore).
    void codeRestoreRequested();
    /// The user asked to delete the backups of generated files (Clear backups).
    void clearBackupsRequested();

private:
    struct Row
    {
        QWidget *editor = nullptr;
        QLabel *message = nullptr;
    };

    void buildForm();
    QWidget *buildButtonRow();
    QFormLayout *addSection(const QString &title);
    void alignLabels(const QList<QFormLayout *> &forms);
    void addLineEdit(QFormLayout *form, BasicField field, const QString &label,
                     const QString &placeholder);
    void addComboBox(QFormLayout *form, BasicField field, const QString &label,
                     const QStringList &items, bool editable);
    void addRow(QFormLayout *form, BasicField field, const QString &label, QWidget *editor);

    void userEdited(BasicField field, const QString &text);
    void refresh(BasicField field);
    void showInComboBox(QComboBox *combo, const QString &value);
    void refreshAll();
    void refreshHeader();
    void showProblem(BasicField field, const QString &text);
    QString problemFor(BasicField field, const QString &text) const;

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    QHash<int, Row> m_rows;
    QLabel *m_title = nullptr;
    QLabel *m_componentId = nullptr;
    QWidget *m_content = nullptr;
    QPushButton *m_generate = nullptr;
    QLabel *m_generationProblems = nullptr;
    bool m_updating = false;
};

} // namespace Builder
