// SPDX-License-Identifier: MIT
#include "userguide.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QScrollBar>
#include <QTextBlock>
#include <QFileInfo>
#include <QImage>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextList>
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
    connect(m_browser, &QTextBrowser::sourceChanged, this, &UserGuide::fitPictures);
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
    fitPictures();
    scrollToPendingSection();
}

void UserGuide::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    fitPictures();
}

// Screenshots are as wide as the windows they show: scaled down to the page's width (less a list's
// indent), each is seen whole without scrolling sideways. Smaller ones keep their size.
void UserGuide::fitPictures()
{
    QTextDocument *document = m_browser->document();
    const qreal width = m_browser->viewport()->width() - document->documentMargin();
    if (width <= 0)
        return;
    struct Picture
    {
        QTextFragment fragment;
        QTextImageFormat format;
        qreal room;
    };
    // Collected first: changing a fragment's format while iterating would split the fragments.
    QList<Picture> pictures;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        // A picture in a list item starts at the item's indent.
        const QTextBlockFormat format = block.blockFormat();
        qreal left = document->documentLayout()->blockBoundingRect(block).left() + format.leftMargin()
            + format.indent() * document->indentWidth();
        if (const QTextList *list = block.textList())
            left += list->format().indent() * document->indentWidth();
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            if (it.fragment().charFormat().isImageFormat())
                pictures.append({it.fragment(), it.fragment().charFormat().toImageFormat(), width - left});
        }
    }
    QTextCursor cursor(document);
    bool changed = false;
    for (Picture &picture : pictures) {
        const QVariant data = m_browser->loadResource(QTextDocument::ImageResource, QUrl(picture.format.name()));
        const QSize natural = data.typeId() == QMetaType::QByteArray ? QImage::fromData(data.toByteArray()).size()
                                                                     : data.value<QImage>().size();
        const qreal shown = std::min<qreal>(natural.width(), picture.room);
        if (natural.isEmpty() || shown <= 0 || qFuzzyCompare(picture.format.width(), shown))
            continue;
        picture.format.setWidth(shown);
        picture.format.setHeight(natural.height() * shown / natural.width());
        cursor.setPosition(picture.fragment.position());
        cursor.setPosition(picture.fragment.position() + picture.fragment.length(), QTextCursor::KeepAnchor);
        cursor.setCharFormat(picture.format);
        changed = true;
    }
    if (changed)
        document->size(); // lays the page out again now: link and heading positions are read from it
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
