// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "executioncontextmodel.h"
#include "executioncontextview.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "onlinesession.h"
#include "orb.h"

#include <QAbstractItemModelTester>
#include <QPushButton>
#include <QSignalSpy>
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

private:
    Corba::ComponentProxy component() const;
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
        "manager.components.precreate=ConsoleIn"};
    QVERIFY2(
        m_live.startProcess(QStringLiteral(RTMANAGER_PATH), arguments, "rtmanager ready", &error),
        qPrintable(error));
}

Corba::ComponentProxy TestOnlineExecutionContext::component() const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/echost.host_cxt/ConsoleIn0.rtc").arg(m_live.namingServer()));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
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

QTEST_MAIN(TestOnlineExecutionContext)
#include "tst_onlineexecutioncontext.moc"
