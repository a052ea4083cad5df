// SPDX-License-Identifier: MIT
#include "perspective.h"

#include "document.h"

#include <QLabel>
#include <QStackedWidget>
#include <QTabWidget>
#include <QVBoxLayout>

namespace Studio {

Perspective::Perspective(Id id, const QString &title, QWidget *parent)
    : QWidget(parent)
    , m_id(id)
    , m_title(title)
    , m_stack(new QStackedWidget(this))
    , m_emptyHint(new QLabel(this))
    , m_tabs(new QTabWidget(this))
{
    m_emptyHint->setAlignment(Qt::AlignCenter);
    m_emptyHint->setWordWrap(true);
    m_emptyHint->setMargin(24);
    // Drawn in the placeholder colour: a hint, not content, yet easy to read.
    QPalette hintPalette = m_emptyHint->palette();
    hintPalette.setColor(QPalette::WindowText, hintPalette.color(QPalette::PlaceholderText));
    m_emptyHint->setPalette(hintPalette);
    QFont hintFont = m_emptyHint->font();
    hintFont.setPointSizeF(hintFont.pointSizeF() * 1.15);
    m_emptyHint->setFont(hintFont);
    m_tabs->setDocumentMode(true);
    m_tabs->setTabsClosable(true);
    m_tabs->setMovable(true);
    m_stack->addWidget(m_emptyHint);
    m_stack->addWidget(m_tabs);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stack);

    connect(m_tabs, &QTabWidget::currentChanged, this,
            [this](int index) { emit currentDocumentChanged(documentAt(index)); });
    connect(m_tabs, &QTabWidget::tabCloseRequested, this, [this](int index) {
        if (Document *document = documentAt(index))
            emit closeRequested(document);
    });
    updateEmptyState();
}

void Perspective::setEmptyHint(const QString &text)
{
    m_emptyHint->setText(text);
}

void Perspective::addDocument(Document *document, QWidget *editor)
{
    m_documentByEditor.insert(editor, document);
    const int index = m_tabs->addTab(editor, QString());
    updateTab(document);
    connect(document, &Document::displayNameChanged, this,
            [this, document] { updateTab(document); });
    connect(document, &Document::filePathChanged, this, [this, document] { updateTab(document); });
    connect(document, &Document::modifiedChanged, this, [this, document] { updateTab(document); });
    updateEmptyState();
    m_tabs->setCurrentIndex(index);
}

void Perspective::removeDocument(Document *document)
{
    const int index = indexOf(document);
    if (index < 0)
        return;
    QWidget *editor = m_tabs->widget(index);
    disconnect(document, nullptr, this, nullptr);
    m_documentByEditor.remove(editor);
    m_tabs->removeTab(index);
    delete editor;
    updateEmptyState();
}

bool Perspective::contains(const Document *document) const
{
    return indexOf(document) >= 0;
}

QList<Document *> Perspective::documents() const
{
    QList<Document *> result;
    for (int i = 0; i < m_tabs->count(); ++i)
        result << documentAt(i);
    return result;
}

Document *Perspective::currentDocument() const
{
    return documentAt(m_tabs->currentIndex());
}

void Perspective::setCurrentDocument(Document *document)
{
    const int index = indexOf(document);
    if (index >= 0)
        m_tabs->setCurrentIndex(index);
}

QWidget *Perspective::editor(const Document *document) const
{
    const int index = indexOf(document);
    return index >= 0 ? m_tabs->widget(index) : nullptr;
}

int Perspective::indexOf(const Document *document) const
{
    for (int i = 0; i < m_tabs->count(); ++i) {
        if (documentAt(i) == document)
            return i;
    }
    return -1;
}

Document *Perspective::documentAt(int index) const
{
    return m_documentByEditor.value(m_tabs->widget(index));
}

void Perspective::updateTab(Document *document)
{
    const int index = indexOf(document);
    if (index < 0)
        return;
    // An asterisk marks unsaved changes, as the window title's [*] does for the current one.
    const QString marker = document->isModified() ? QStringLiteral("*") : QString();
    m_tabs->setTabText(index, document->displayName() + marker);
    m_tabs->setTabToolTip(index,
                          document->isUntitled() ? tr("Not saved yet") : document->filePath());
}

void Perspective::updateEmptyState()
{
    m_stack->setCurrentWidget(m_tabs->count() > 0 ? static_cast<QWidget *>(m_tabs) : m_emptyHint);
}

} // namespace Studio
