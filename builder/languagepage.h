// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QLineEdit;
class QTableView;
class QUndoStack;

namespace Builder {

class LibraryTableModel;

/**
 * The Builder's "Language/Environment" page: the language (C++, Python, Java), and the target
 * environment — language version, OS, OS versions, CPUs — with its libraries.
 */
class LanguagePage : public QWidget
{
    Q_OBJECT

public:
    enum class Field { Kind, LangVersion, Os, OsVersions, Cpus };

    LanguagePage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    QWidget *editor(Field field) const;
    QTableView *libraries() const { return m_libraries; }
    LibraryTableModel *libraryTable() const { return m_libraryTable; }

    /// The languages offered.
    static QStringList languages();

private:
    void refresh();
    void userEdited(Field field, const QString &text);

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    QComboBox *m_kind;
    QList<QLineEdit *> m_edits; ///< LangVersion, Os, OsVersions, Cpus
    LibraryTableModel *m_libraryTable;
    QTableView *m_libraries;
    bool m_updating = false;
};

} // namespace Builder
