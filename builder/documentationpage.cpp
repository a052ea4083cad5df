// SPDX-License-Identifier: MIT
#include "documentationpage.h"

#include "componentcommands.h"

#include <QFormLayout>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

using Member = std::optional<QString> Profile::RtcBasicDoc::*;

struct FieldInfo
{
    DocumentationPage::Field field;
    Member member;
    const char *key;
    const char *label;
    int lines;
};

const FieldInfo Fields[] = {
    {DocumentationPage::Field::Description, &Profile::RtcBasicDoc::description, "description",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&Description:"), 4},
    {DocumentationPage::Field::InOut, &Profile::RtcBasicDoc::inout, "inout",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&Input and output:"), 3},
    {DocumentationPage::Field::Algorithm, &Profile::RtcBasicDoc::algorithm, "algorithm",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&Algorithm:"), 3},
    {DocumentationPage::Field::Reference, &Profile::RtcBasicDoc::reference, "reference",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&Reference:"), 2},
    {DocumentationPage::Field::Creator, &Profile::RtcBasicDoc::creator, "creator",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&Creator and contact:"), 1},
    {DocumentationPage::Field::License, &Profile::RtcBasicDoc::license, "license",
     QT_TRANSLATE_NOOP("Builder::DocumentationPage", "&License:"), 2},
};

} // namespace

DocumentationPage::DocumentationPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    auto *content = new QWidget;
    auto *contentLayout = new QVBoxLayout(content);
    auto *form = new QFormLayout;
    contentLayout->addLayout(form);
    contentLayout->addStretch(1);
    for (const FieldInfo &info : Fields) {
        auto *edit = new QPlainTextEdit(content);
        edit->setTabChangesFocus(true);
        const int height = edit->fontMetrics().lineSpacing() * info.lines + 12;
        edit->setFixedHeight(height);
        if (info.field == Field::Creator)
            edit->setPlaceholderText(tr("Name <mail@example.org>"));
        connect(edit, &QPlainTextEdit::textChanged, this, [this, field = info.field] {
            if (!m_updating)
                userEdited(field);
        });
        form->addRow(tr(info.label), edit);
        m_editors << edit;
    }
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(content);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
    connect(model, &ComponentModel::componentDocChanged, this, &DocumentationPage::refresh);
    connect(model, &ComponentModel::profileReset, this, &DocumentationPage::refresh);
    refresh();
}

QPlainTextEdit *DocumentationPage::editor(Field field) const
{
    return m_editors.at(int(field));
}

void DocumentationPage::refresh()
{
    if (!m_model)
        return;
    const auto &doc = m_model->profile().basicInfo.doc;
    m_updating = true;
    for (const FieldInfo &info : Fields) {
        const QString text = doc ? ((*doc).*info.member).value_or(QString()) : QString();
        QPlainTextEdit *edit = editor(info.field);
        if (edit->toPlainText() != text)
            edit->setPlainText(text);
    }
    m_updating = false;
}

void DocumentationPage::userEdited(Field field)
{
    const FieldInfo &info = Fields[int(field)];
    const QString text = editor(field)->toPlainText();
    std::optional<Profile::RtcBasicDoc> doc = m_model->profile().basicInfo.doc;
    // Clearing a text that was absent leaves the file as it was.
    if (text.isEmpty() && (!doc || !((*doc).*info.member)))
        return;
    if (!doc)
        doc = Profile::RtcBasicDoc();
    (*doc).*info.member = text;
    if (doc == m_model->profile().basicInfo.doc)
        return;
    m_undoStack->push(new SetComponentDocCommand(m_model, doc, QLatin1String(info.key)));
}

} // namespace Builder
