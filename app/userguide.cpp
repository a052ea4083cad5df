// SPDX-License-Identifier: MIT
#include "userguide.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QScrollBar>
#include <QTextBlock>
#include <QFileInfo>
#include <QTextBrowser>
#include <QToolBar>
#include <QUrl>
#include <QVBoxLayout>

namespace Studio {

UserGuide::UserGuide(QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_browser(new QTextBrowser)
{
    setObjectName(QStringLiteral("userGuide"));
    setWindowTitle(tr("RT Studio User Guide"));
    resize(900, 700);
    m_browser->setObjectName(QStringLiteral("userGuideBrowser"));
    m_browser->setOpenExternalLinks(true);
    auto *bar = new QToolBar;
    m_back = bar->addAction(tr("Back"), m_browser, &QTextBrowser::backward);
    m_forward = bar->addAction(tr("Forward"), m_browser, &QTextBrowser::forward);
    m_back->setShortcut(QKeySequence::Back);
    m_forward->setShortcut(QKeySequence::Forward);
    m_back->setEnabled(false);
    m_forward->setEnabled(false);
    connect(m_browser, &QTextBrowser::backwardAvailable, m_back, &QAction::setEnabled);
    connect(m_browser, &QTextBrowser::forwardAvailable, m_forward, &QAction::setEnabled);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(bar);
    layout->addWidget(m_browser, 1);
}

QString UserGuide::page(const QString &name, const QString &language)
{
    const QString translated = Root + QStringLiteral("docs/%1/%2").arg(language, name);
    if (language != QLatin1String("en") && QFileInfo::exists(translated))
        return translated;
    const QString english = Root + QStringLiteral("docs/") + name;
    return QFileInfo::exists(english) ? english : QString();
}

void UserGuide::showSection(const QString &name, const QString &section, const QString &language)
{
    showPage(name, language);
    m_pendingSection = section;
    if (isVisible())
        scrollToPendingSection();
}

void UserGuide::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    scrollToPendingSection();
}

// Markdown headings get no anchors in QTextDocument: find the heading block and scroll to it, once
// the window has its size (the scroll range depends on it).
void UserGuide::scrollToPendingSection()
{
    const QString section = std::exchange(m_pendingSection, QString());
    if (section.isEmpty())
        return;
    m_browser->document()->size(); // lays the whole page out, so the range covers the heading
    for (QTextBlock block = m_browser->document()->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() > 0 && block.text() == section) {
            const QRectF rect = m_browser->document()->documentLayout()->blockBoundingRect(block);
            m_browser->verticalScrollBar()->setValue(int(rect.top()));
            return;
        }
    }
}

QString UserGuide::sectionAtTop() const
{
    const int top = m_browser->verticalScrollBar()->value();
    QAbstractTextDocumentLayout *layout = m_browser->document()->documentLayout();
    for (QTextBlock block = m_browser->document()->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() > 0 && qAbs(int(layout->blockBoundingRect(block).top()) - top) <= 1)
            return block.text();
    }
    return {};
}

void UserGuide::showPage(const QString &name, const QString &language)
{
    const QString path = page(name, language);
    if (!path.isEmpty())
        m_browser->setSource(QUrl(QStringLiteral("qrc") + path), QTextDocument::MarkdownResource);
}

} // namespace Studio
