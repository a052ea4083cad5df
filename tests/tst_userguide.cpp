// SPDX-License-Identifier: MIT
// Help → User Guide and Help → Troubleshooting show the guide inside the program: README.md and
// every page of docs/ are built in, links between pages are followed in the window, and a page
// translated into the GUI's language is shown in it.
#include "componenteditor.h"
#include "mainwindow.h"
#include "onlinediagram.h"
#include "onlinedocks.h"
#include "onlinedocument.h"
#include "portmonitor.h"
#include "nameserviceview.h"
#include "planview.h"
#include "rtseditor.h"
#include "userguide.h"

#include <QAbstractItemView>
#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QDockWidget>
#include <QGraphicsView>
#include <QDir>
#include <QDirIterator>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QImage>
#include <QPixmap>

using Studio::UserGuide;

namespace {

/// Where in @p browser's viewport the first link to @p href is, scrolled into view; null when none.
QPoint linkPosition(QTextBrowser *browser, const QString &href)
{
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (fragment.charFormat().anchorHref() != href)
                continue;
            QTextCursor cursor(browser->document());
            cursor.setPosition(fragment.position() + fragment.length() / 2);
            browser->setTextCursor(cursor);
            browser->ensureCursorVisible();
            return browser->cursorRect(cursor).center();
        }
    }
    return {};
}

/// True when @p browser shows the heading @p section: at the top, or on screen when the page ends too
/// soon after it to scroll it there.
bool showsHeading(QTextBrowser *browser, const QString &section)
{
    QAbstractTextDocumentLayout *layout = browser->document()->documentLayout();
    const int top = browser->verticalScrollBar()->value();
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0 || block.text() != section)
            continue;
        const int at = int(layout->blockBoundingRect(block).top());
        return qAbs(at - top) <= 1
            || (top == browser->verticalScrollBar()->maximum() && at > top && at < top + browser->viewport()->height());
    }
    return false;
}

} // namespace

class TestUserGuide : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void everyPageIsBuiltIn();
    void helpShowsGettingStarted();
    void linksAreFollowed();
    void picturesAreShown_data();
    void picturesAreShown();
    void troubleshooting();
    void f1ShowsTheSectionOfTheViewInFront();
    void japanesePagesFirst();

private:
    QTemporaryDir m_settingsDir;
};

void TestUserGuide::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_userguide"));
}

void TestUserGuide::everyPageIsBuiltIn()
{
    QStringList pages{QStringLiteral("README.md")};
    QDirIterator it(RTSTUDIO_SOURCE_DIR + QStringLiteral("/docs"), {QStringLiteral("*.md")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        pages << QDir(RTSTUDIO_SOURCE_DIR).relativeFilePath(it.next());
    QVERIFY(pages.size() > 4);
    for (const QString &page : std::as_const(pages))
        QVERIFY2(QFile::exists(UserGuide::Root + page), qPrintable(page + QStringLiteral(" is not built in")));
}

void TestUserGuide::helpShowsGettingStarted()
{
    Studio::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto *action = window.findChild<QAction *>(QStringLiteral("actionUserGuide"));
    QVERIFY(action);
    QVERIFY(!window.userGuide());
    action->trigger();
    UserGuide *guide = window.userGuide();
    QVERIFY(guide);
    QVERIFY(QTest::qWaitForWindowExposed(guide));
    QVERIFY2(guide->browser()->source().path().endsWith(QStringLiteral("docs/getting-started.md")),
             qPrintable(guide->browser()->source().toString()));
    const QString text = guide->browser()->toPlainText();
    QVERIFY2(text.startsWith(QStringLiteral("Getting started")), qPrintable(text.left(200)));
    QVERIFY(!text.contains(QStringLiteral("](")));  // rendered, not shown as Markdown
    // Asked again, the same window comes back.
    action->trigger();
    QCOMPARE(window.userGuide(), guide);
}

void TestUserGuide::picturesAreShown_data()
{
    QTest::addColumn<QString>("page");
    QTest::addColumn<QString>("language");
    QTest::newRow("getting started") << QStringLiteral("getting-started.md") << QStringLiteral("en");
    QTest::newRow("はじめに") << QStringLiteral("getting-started.md") << QStringLiteral("ja");
    QTest::newRow("the IDE") << QStringLiteral("rtstudio.md") << QStringLiteral("en");
}

// The screenshots a page shows are built in with it: each image of the page loads.
void TestUserGuide::picturesAreShown()
{
    QFETCH(QString, page);
    QFETCH(QString, language);
    UserGuide guide;
    guide.showPage(page, language);
    QTextBrowser *browser = guide.browser();
    QStringList images;
    QStringList missing;
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextCharFormat format = it.fragment().charFormat();
            if (!format.isImageFormat())
                continue;
            const QString name = format.toImageFormat().name();
            images << name;
            const QVariant image = browser->loadResource(QTextDocument::ImageResource, QUrl(name));
            if (image.value<QImage>().isNull() && image.value<QPixmap>().isNull()
                && image.toByteArray().isEmpty())
                missing << name;
        }
    }
    QVERIFY2(images.size() >= 2, qPrintable(images.join(", ")));
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("not built in: ") + missing.join(", ")));
    // Shown, each fits the window's width: nothing to scroll sideways for.
    guide.resize(900, 700);
    guide.show();
    QVERIFY(QTest::qWaitForWindowExposed(&guide));
    QCOMPARE(browser->horizontalScrollBar()->maximum(), 0);
}

void TestUserGuide::linksAreFollowed()
{
    UserGuide guide;
    guide.showPage(QStringLiteral("getting-started.md"), QStringLiteral("en"));
    QTextBrowser *browser = guide.browser();
    guide.show();
    QVERIFY(QTest::qWaitForWindowExposed(&guide));
    // A click on the page's link to the troubleshooting page.
    const QPoint link = linkPosition(browser, QStringLiteral("troubleshooting.md"));
    QVERIFY(!link.isNull());
    QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, link);
    QVERIFY2(browser->source().path().endsWith(QStringLiteral("docs/troubleshooting.md")),
             qPrintable(browser->source().toString()));
    QVERIFY(browser->toPlainText().startsWith(QStringLiteral("Troubleshooting")));
    QVERIFY(browser->isBackwardAvailable());
    browser->backward();
    QVERIFY(browser->toPlainText().startsWith(QStringLiteral("Getting started")));
    // Up to the README, which links into docs/ again.
    QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, linkPosition(browser, QStringLiteral("../README.md")));
    QVERIFY2(browser->toPlainText().startsWith(QStringLiteral("RT Studio")), qPrintable(browser->source().toString()));
    QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, linkPosition(browser, QStringLiteral("docs/rtctl.md")));
    QVERIFY2(browser->toPlainText().startsWith(QStringLiteral("rtctl")), qPrintable(browser->source().toString()));
}

void TestUserGuide::troubleshooting()
{
    Studio::MainWindow window;
    auto *action = window.findChild<QAction *>(QStringLiteral("actionTroubleshooting"));
    QVERIFY(action);
    action->trigger();
    QVERIFY(window.userGuide());
    QVERIFY(window.userGuide()->browser()->toPlainText().startsWith(QStringLiteral("Troubleshooting")));
}

void TestUserGuide::f1ShowsTheSectionOfTheViewInFront()
{
    Studio::MainWindow window;
    window.resize(1000, 700);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto *help = window.findChild<QAction *>(QStringLiteral("actionContextHelp"));
    QVERIFY(help);
    QCOMPARE(help->shortcut(), QKeySequence(QKeySequence::HelpContents));
    const QString examples = RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/");
    const auto pressF1 = [&window] {
        QTest::keyClick(&window, Qt::Key_F1);
        QVERIFY(window.userGuide());
        QVERIFY(window.userGuide()->browser()->source().path().endsWith(QStringLiteral("docs/rtstudio.md")));
    };
    QVERIFY(window.openFiles({examples + QStringLiteral("tour/Doubler.xml")}));
    pressF1();
    QCOMPARE(window.userGuide()->sectionAtTop(), QStringLiteral("Basic page"));
    // Each Builder page has its section.
    auto *editor = window.findChild<Builder::ComponentEditor *>();
    QVERIFY(editor);
    for (int page = 0; page < editor->pages()->count(); ++page) {
        editor->pages()->setCurrentIndex(page);
        window.activateWindow();
        pressF1();
        QCOMPARE(window.userGuide()->sectionAtTop(), editor->helpSection());
        QVERIFY(editor->helpSection().endsWith(QLatin1String(" page")));
    }
    QVERIFY(window.openFiles({examples + QStringLiteral("ConsoleInOut/ConsoleInOut.xml")}));
    window.activateWindow();
    pressF1();
    QCOMPARE(window.userGuide()->sectionAtTop(), QStringLiteral("System Editor"));
    // A view with a section of its own, when it has the focus.
    Studio::RtsEditor *system = nullptr;
    for (Studio::RtsEditor *candidate : window.findChildren<Studio::RtsEditor *>())
        system = candidate->isVisible() ? candidate : system;
    QVERIFY(system);
    system->showPlanView(true);
    QApplication::processEvents();
    system->planView()->setFocus();
    QTRY_VERIFY(system->planView()->hasFocus() || system->planView()->isAncestorOf(QApplication::focusWidget()));
    window.activateWindow();
    pressF1();
    QCOMPARE(window.userGuide()->sectionAtTop(), QStringLiteral("Plan view"));
    // The online views: the Name Service dock, the Port Monitor and an online diagram's tab.
    window.findChild<QAction *>(QStringLiteral("actionNewOnlineDiagram"))->trigger();
    auto *online = qobject_cast<Studio::OnlineDocument *>(window.activeDocument());
    QVERIFY(online);
    const std::pair<QWidget *, QString> views[]
        = {{window.onlineDocks()->nameService(), QStringLiteral("Online")},
           {window.onlineDocks()->portMonitor(), QStringLiteral("Port Monitor")},
           {online->diagram()->view(), QStringLiteral("Online")}};
    for (const auto &[view, section] : views) {
        for (QDockWidget *dock : window.onlineDocks()->docks()) {
            if (dock->isAncestorOf(view))
                dock->show();
        }
        QWidget *target = view->focusPolicy() != Qt::NoFocus ? view : view->findChild<QAbstractItemView *>();
        QVERIFY(target);
        target->setFocus();
        QTRY_VERIFY(target->hasFocus());
        window.activateWindow();
        pressF1();
        QVERIFY2(showsHeading(window.userGuide()->browser(), section), qPrintable(section));
    }
    // A heading the page lacks shows its top.
    UserGuide guide;
    guide.showSection(QStringLiteral("rtstudio.md"), QStringLiteral("No Such Heading"), QStringLiteral("en"));
    QCOMPARE(guide.browser()->verticalScrollBar()->value(), 0);
}

void TestUserGuide::japanesePagesFirst()
{
    QCOMPARE(UserGuide::page(QStringLiteral("getting-started.md"), QStringLiteral("ja")),
             UserGuide::Root + QStringLiteral("docs/ja/getting-started.md"));
    // Pages without a translation are shown in English.
    QCOMPARE(UserGuide::page(QStringLiteral("rtctl.md"), QStringLiteral("ja")),
             UserGuide::Root + QStringLiteral("docs/rtctl.md"));
    QCOMPARE(UserGuide::page(QStringLiteral("getting-started.md"), QStringLiteral("en")),
             UserGuide::Root + QStringLiteral("docs/getting-started.md"));
    QCOMPARE(UserGuide::page(QStringLiteral("nothing.md"), QStringLiteral("en")), QString());
    UserGuide guide;
    guide.showPage(QStringLiteral("troubleshooting.md"), QStringLiteral("ja"));
    QVERIFY(guide.browser()->toPlainText().startsWith(QStringLiteral("トラブルシューティング")));
    if (qEnvironmentVariableIsSet("RTSTUDIO_SCREENSHOT_DIR")) {
        const QDir shots(qEnvironmentVariable("RTSTUDIO_SCREENSHOT_DIR"));
        guide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&guide));
        guide.grab().save(shots.filePath(QStringLiteral("userguide-ja.png")));
        guide.showPage(QStringLiteral("getting-started.md"), QStringLiteral("en"));
        guide.grab().save(shots.filePath(QStringLiteral("userguide-en.png")));
    }
}

QTEST_MAIN(TestUserGuide)
#include "tst_userguide.moc"
