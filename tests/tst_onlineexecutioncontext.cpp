// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "executioncontextmodel.h"
#include "executioncontextview.h"
#include "livesystem.h"
#include "nameservicemodel.h"
#include "namingbrowser.h"
#include "onlinecalls.h"
#include "onlinesession.h"
#include "orb.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>

using namespace SystemEditor;
using Column = ExecutionContextModel::Column;

// The Execution Context view against a component running in a real rtmanager.
class TestOnlineExecutionContext : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void listsTheContexts();
    void startsStopsAndSetsTheRate();
    void activatesInTheSelectedContext();
    void attachesAndDetachesOtherComponents();

private:
    Corba::ComponentProxy component(const QString &instance = QStringLiteral("ConsoleIn0")) const;
    void fillNames(NameServiceModel &names) const;
    void popupAction(QPushButton *button, const QString &text, QAction *&found);
    void load(ExecutionContextView &view);
    QString cell(ExecutionContextView &view, Column column) const;
    void performAndWait(ExecutionContextView &view, const std::function<void()> &action);

    LiveTest::LiveSystem m_live;
};

void TestOnlineExecutionContext::initTestCase()
{
    Corba::Orb::setCallTimeout(3000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList arguments {
        "-d",
        "-o",
        QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(LiveTest::freePort()),
        "-o",
        "corba.nameservers=" + m_live.namingServer(),
        "-o",
        "naming.formats=echost.host_cxt/%n.rtc",
        "-o",
        "manager.naming_formats=echost.host_cxt/%n.mgr",
        "-o",
        "manager.components.precreate=ConsoleIn,ConsoleOut"};
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error),
        qPrintable(error));
}

Corba::ComponentProxy TestOnlineExecutionContext::component(const QString &instance) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/echost.host_cxt/%2.rtc").arg(m_live.namingServer(), instance));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestOnlineExecutionContext::fillNames(NameServiceModel &names) const
{
    QVERIFY(names.addServer(m_live.namingServer()));
    const ServerSnapshot snapshot = OnlineCalls::fetchServer(names.servers().front());
    names.setServerTree(snapshot.server, snapshot.tree, snapshot.states);
}

// What a click on a menu item does: the action fires and its popup closes.
static void choose(QAction *action)
{
    action->trigger();
    while (QWidget *popup = QApplication::activePopupWidget())
        popup->close();
}

// Clicks `button` and finds the action called `text` in the menu it pops up.
void TestOnlineExecutionContext::popupAction(QPushButton *button, const QString &text,
                                             QAction *&found)
{
    found = nullptr;
    QTest::mouseClick(button, Qt::LeftButton);
    QMenu *menu = nullptr;
    QTRY_VERIFY((menu = qobject_cast<QMenu *>(QApplication::activePopupWidget())));
    for (QAction *action : menu->actions()) {
        if (action->text() == text)
            found = action;
    }
}

void TestOnlineExecutionContext::load(ExecutionContextView &view)
{
    QSignalSpy loaded(&view, &ExecutionContextView::loaded);
    const Corba::ComponentProxy proxy = component();
    view.setComponent(proxy.path(), proxy.ior());
    QVERIFY(loaded.wait(10000));
}

QString TestOnlineExecutionContext::cell(ExecutionContextView &view, Column column) const
{
    return view.model()->index(0, column).data().toString();
}

void TestOnlineExecutionContext::performAndWait(ExecutionContextView &view,
                                                const std::function<void()> &action)
{
    QSignalSpy finished(&view, &ExecutionContextView::actionFinished);
    QSignalSpy loaded(&view, &ExecutionContextView::loaded);
    action();
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), QString());
    QVERIFY(loaded.wait(10000));
}

void TestOnlineExecutionContext::listsTheContexts()
{
    OnlineSession session;
    ExecutionContextView view(&session);
    QAbstractItemModelTester tester(view.model(),
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    load(view);
    QCOMPARE(view.model()->rowCount(), 1);
    QCOMPARE(cell(view, Column::RelationColumn), QStringLiteral("owned"));
    QCOMPARE(cell(view, Column::KindColumn), QStringLiteral("PERIODIC"));
    QCOMPARE(cell(view, Column::RunningColumn), QStringLiteral("Running"));
    QCOMPARE(cell(view, Column::StateColumn), QStringLiteral("Inactive"));
    QVERIFY(view.model()->index(0, Column::RateColumn).data().toDouble() > 0);
    QCOMPARE(view.currentContext(), 0);
}

void TestOnlineExecutionContext::startsStopsAndSetsTheRate()
{
    OnlineSession session;
    ExecutionContextView view(&session);
    QAbstractItemModelTester tester(view.model(),
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    load(view);
    performAndWait(view, [&] {
        QTest::mouseClick(view.findChild<QPushButton *>("stopButton"), Qt::LeftButton);
    });
    QCOMPARE(cell(view, Column::RunningColumn), QStringLiteral("Stopped"));
    QVERIFY(!component().executionContexts().front().running);
    performAndWait(view, [&] { view.perform(ExecutionContextView::Action::Start, 0); });
    QCOMPARE(cell(view, Column::RunningColumn), QStringLiteral("Running"));
    performAndWait(view, [&] { view.setRate(25, 0); });
    QCOMPARE(view.model()->index(0, Column::RateColumn).data().toDouble(), 25.0);
    QCOMPARE(component().executionContexts().front().rate, 25.0);
}

void TestOnlineExecutionContext::activatesInTheSelectedContext()
{
    OnlineSession session;
    ExecutionContextView view(&session);
    load(view);
    performAndWait(view, [&] {
        QTest::mouseClick(view.findChild<QPushButton *>("activateButton"), Qt::LeftButton);
    });
    QCOMPARE(cell(view, Column::StateColumn), QStringLiteral("Active"));
    QCOMPARE(component().state(0), Corba::LifeCycleState::Active);
    performAndWait(view, [&] { view.perform(ExecutionContextView::Action::Deactivate, 0); });
    QCOMPARE(cell(view, Column::StateColumn), QStringLiteral("Inactive"));
    QSignalSpy finished(&view, &ExecutionContextView::actionFinished);
    view.perform(ExecutionContextView::Action::Start, 3); // no such context
    QVERIFY(finished.wait(10000));
    QVERIFY(!finished.at(0).at(0).toString().isEmpty());
}

void TestOnlineExecutionContext::attachesAndDetachesOtherComponents()
{
    OnlineSession session;
    NameServiceModel names;
    fillNames(names);
    const Corba::ComponentProxy guest = component(QStringLiteral("ConsoleOut0"));
    ExecutionContextView view(&session);
    view.setComponentSource(&names);
    view.show();
    load(view);
    QCOMPARE(cell(view, Column::OwnerColumn), QStringLiteral("ConsoleIn0"));
    QCOMPARE(cell(view, Column::ParticipantsColumn), QString());
    QCOMPARE(view.attachCandidates(0).size(), 1);
    QCOMPARE(view.attachCandidates(0).front().name, guest.path());

    QAction *attach = nullptr;
    popupAction(view.findChild<QPushButton *>("attachButton"), guest.path(), attach);
    QVERIFY(attach);
    performAndWait(view, [&] { choose(attach); });
    QCOMPARE(cell(view, Column::ParticipantsColumn), QStringLiteral("ConsoleOut0"));
    QCOMPARE(guest.executionContexts().size(), size_t(2));
    QVERIFY(view.attachCandidates(0).isEmpty());
    QCOMPARE(view.detachCandidates(0).size(), 1);

    // The guest's own view lists the borrowed context with its owner and leaves it.
    view.setComponent(guest.path(), guest.ior());
    QSignalSpy loaded(&view, &ExecutionContextView::loaded);
    QVERIFY(loaded.wait(10000));
    QCOMPARE(view.model()->rowCount(), 2);
    QCOMPARE(view.model()->index(1, Column::RelationColumn).data().toString(),
             QStringLiteral("participating"));
    QCOMPARE(view.model()->index(1, Column::OwnerColumn).data().toString(),
             QStringLiteral("ConsoleIn0"));
    view.tableView()->selectRow(1);
    QVERIFY(view.detachCandidates(0).isEmpty()); // nobody else takes part in its own context
    QAction *detach = nullptr;
    popupAction(view.findChild<QPushButton *>("detachButton"), guest.path(), detach);
    QVERIFY(detach);
    performAndWait(view, [&] { choose(detach); });
    QCOMPARE(view.model()->rowCount(), 1);
    QCOMPARE(component()
                 .executionContexts(Corba::ComponentProxy::ContextDetail::Members)
                 .front()
                 .participants.size(),
             size_t(0));

    // The table's menu offers the same, and a refused attach is reported, not lost.
    std::unique_ptr<QMenu> menu(view.createContextMenu(0));
    QMenu *attachMenu = menu->findChild<QMenu *>("attachMenu");
    QVERIFY(attachMenu);
    QCOMPARE(attachMenu->actions().size(), 1);
    QCOMPARE(attachMenu->actions().front()->text(), component().path());
    QVERIFY(!menu->findChild<QMenu *>("detachMenu")->actions().front()->isEnabled());
    QSignalSpy finished(&view, &ExecutionContextView::actionFinished);
    view.attach(0, {guest.path(), guest.ior()}); // owns it already
    QVERIFY(finished.wait(10000));
    QVERIFY2(finished.at(0).at(0).toString().contains("owns"),
             qPrintable(finished.at(0).at(0).toString()));
}

QTEST_MAIN(TestOnlineExecutionContext)
#include "tst_onlineexecutioncontext.moc"
