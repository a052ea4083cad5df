// SPDX-License-Identifier: MIT
#pragma once

#include "rtsdocument.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QFormLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace Studio {

/**
 * The System Editor's "system info": vendor, system name, version (the parts of the system id)
 * and the abstract of an RtsDocument, with the id and dates shown read-only.
 *
 * Edits are pushed as EditSystemInfoCommand onto the document's undo stack; the form refreshes
 * from the document's signals only.
 */
class SystemInfoForm : public QWidget
{
    Q_OBJECT

public:
    explicit SystemInfoForm(RtsDocument *document, QWidget *parent = nullptr);

    /// The editor of a field: a QLineEdit, or a QPlainTextEdit for the abstract.
    QWidget *editor(RtsDocument::SystemField field) const;
    /// The problem marked under a field; empty when there is none.
    QString problem(RtsDocument::SystemField field) const;

private:
    void addIdRow(QFormLayout *form, RtsDocument::SystemField field, const QString &label);
    void userEdited(RtsDocument::SystemField field, const QString &text);
    void refresh();
    void showProblem(RtsDocument::SystemField field, const QString &text);

    QPointer<RtsDocument> m_document;
    QHash<int, QLineEdit *> m_lineEdits;
    QHash<int, QLabel *> m_messages;
    QPlainTextEdit *m_abstract = nullptr;
    QLabel *m_systemId = nullptr;
    QLabel *m_dates = nullptr;
    bool m_updating = false;
};

} // namespace Studio
