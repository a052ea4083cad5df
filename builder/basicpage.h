// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "diagnostic.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QUndoStack;

namespace Builder {

/**
 * The Builder's "Basic" page: name, description, version, vendor, category, abstract, RTC type,
 * component type, activity type, component kind (DataFlow / FSM / MultiMode check boxes), max
 * instances, execution type and rate of a component, the languages to generate (C++ / Python /
 * Java check boxes over the same field as the Language page's language), and the buttons
 * Generate, Code Restore, Clear Backups, Import and Export.
 *
 * Every change the user makes is pushed as an undo command (SetBasicFieldCommand,
 * SetLanguageCommand, one ReplaceProfileCommand per import); the page itself only shows what the
 * model says (it refreshes on the model's signals, including after undo). Problems (e.g. a
 * character the name rule forbids, no component kind chosen) are marked inline under the field.
 */
class BasicPage : public QWidget
{
    Q_OBJECT

public:
    BasicPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    /// The editor of a field: a QLineEdit, a QComboBox for the choice fields, a QPlainTextEdit
    /// for the abstract, the box holding the check boxes for the component kind.
    QWidget *editor(BasicField field) const;
    /// The check box of a component kind part (KindChoices::componentKindParts()).
    QCheckBox *componentKindBox(const QString &part) const;
    /// The check box of a language (KindChoices::languages()).
    QCheckBox *languageBox(const QString &language) const;
    /// The problem marked under the languages; empty when there is none.
    QString languageProblem() const;
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

    /**
     * Replaces the component by the profile in `path` (RTC.xml or YAML) as one undo step.
     * False when nothing was imported; the reason is shown under the buttons.
     */
    bool importProfile(const QString &path);
    /// Writes the profile to `path` (XML or YAML by extension); false with the reason shown.
    bool exportProfile(const QString &path);
    /// What the last import or export said (success or the problems); empty before any.
    QString transferMessage() const;

signals:
    /// The user asked to generate code (the Generate button).
    void generateRequested();
    /// The user asked to restore generated code from a backup (Code restore).
    void codeRestoreRequested();
    /// The user asked to delete the backups of generated files (Clear backups).
    void clearBackupsRequested();
    /// An import or export failed with these problems (also shown on the page).
    void transferFailed(const Profile::Diagnostics &problems);

private:
    struct Row
    {
        QWidget *editor = nullptr;
        QLabel *message = nullptr;
    };

    void buildForm();
    QWidget *buildButtonRow();
    QWidget *buildTransferButtons(QWidget *parent);
    void askTransferFile(bool import);
    void showTransferResult(const QString &text, const Profile::Diagnostics &problems);
    QFormLayout *addSection(const QString &title);
    void alignLabels(const QList<QFormLayout *> &forms);
    void addLineEdit(QFormLayout *form, BasicField field, const QString &label,
                     const QString &placeholder);
    void addComboBox(QFormLayout *form, BasicField field, const QString &label,
                     const QStringList &items, bool editable);
    void addRow(QFormLayout *form, BasicField field, const QString &label, QWidget *editor);
    void addAbstractEdit(QFormLayout *form);
    void addKindBoxes(QFormLayout *form);
    void addLanguageBoxes(QFormLayout *form);
    QWidget *addCheckBoxes(const QStringList &names, const QStringList &labels,
                           QHash<QString, QCheckBox *> *boxes,
                           const std::function<void(const QString &, bool)> &toggled);
    void toggleKind(const QString &part, bool on);
    void toggleLanguage(const QString &language, bool on);
    void refreshLanguages();

    void userEdited(BasicField field, const QString &text);
    void refresh(BasicField field);
    void showInEditor(QWidget *editor, const QString &value);
    void showInComboBox(QComboBox *combo, const QString &value);
    void refreshAll();
    void refreshHeader();
    void showProblem(BasicField field, const QString &text);
    QString problemFor(BasicField field, const QString &text) const;

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    QHash<int, Row> m_rows;
    QHash<QString, QCheckBox *> m_kindBoxes;
    QHash<QString, QCheckBox *> m_languageBoxes;
    QLabel *m_languageMessage = nullptr;
    QLabel *m_transferMessage = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_componentId = nullptr;
    QWidget *m_content = nullptr;
    QPushButton *m_generate = nullptr;
    QLabel *m_generationProblems = nullptr;
    bool m_updating = false;
};

} // namespace Builder
