// SPDX-License-Identifier: MIT
#pragma once

#include "rtcdocument.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;

namespace Studio {

/**
 * The Builder's "Basic" page: name, description, version, vendor, category, component and
 * activity type, max instances, execution type and rate of an RtcDocument.
 *
 * Every change the user makes is pushed as a SetBasicFieldCommand onto the document's undo
 * stack; the page itself only shows what the document says (it refreshes on the document's
 * signals, including after undo). Problems (e.g. a character the name rule forbids) are marked
 * inline under the field.
 */
class BasicPage : public QWidget
{
    Q_OBJECT

public:
    explicit BasicPage(RtcDocument *document, QWidget *parent = nullptr);

    /// The editor of a field: a QLineEdit, or a QComboBox for the choice fields.
    QWidget *editor(RtcDocument::BasicField field) const;
    /// The problem marked under a field; empty when there is none.
    QString problem(RtcDocument::BasicField field) const;

    /// RTC Builder's preset categories.
    static QStringList categoryPresets();
    /// The execution contexts offered for execution type.
    static QStringList executionTypePresets();

private:
    struct Row
    {
        QWidget *editor = nullptr;
        QLabel *message = nullptr;
    };

    void buildForm();
    QFormLayout *addSection(const QString &title);
    void alignLabels(const QList<QFormLayout *> &forms);
    void addLineEdit(QFormLayout *form, RtcDocument::BasicField field, const QString &label,
                     const QString &placeholder);
    void addComboBox(QFormLayout *form, RtcDocument::BasicField field, const QString &label,
                     const QStringList &items, bool editable);
    void addRow(QFormLayout *form, RtcDocument::BasicField field, const QString &label,
                QWidget *editor);

    void userEdited(RtcDocument::BasicField field, const QString &text);
    void refresh(RtcDocument::BasicField field);
    void showInComboBox(QComboBox *combo, const QString &value);
    void refreshAll();
    void refreshHeader();
    void showProblem(RtcDocument::BasicField field, const QString &text);
    QString problemFor(RtcDocument::BasicField field, const QString &text) const;

    QPointer<RtcDocument> m_document;
    QHash<int, Row> m_rows;
    QLabel *m_title = nullptr;
    QLabel *m_componentId = nullptr;
    QWidget *m_content = nullptr;
    bool m_updating = false;
};

} // namespace Studio
