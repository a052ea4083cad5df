// SPDX-License-Identifier: MIT
#include "userguide.h"

#include <QAction>
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

void UserGuide::showPage(const QString &name, const QString &language)
{
    const QString path = page(name, language);
    if (!path.isEmpty())
        m_browser->setSource(QUrl(QStringLiteral("qrc") + path), QTextDocument::MarkdownResource);
}

} // namespace Studio
