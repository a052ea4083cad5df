// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "iorendpoint.h"
#include "livesystem.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinesession.h"
#include "orb.h"
#include "stallmeter.h"
#include "stoppedprocess.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeView>

using namespace SystemEditor;
using Corba::LifeCycleState;
using Corba::NodeType;

// The Name Service view and its worker layer against real omniNames and rtmanager processes.
class TestOnlineNameService : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void normalisesServerAddresses_data();
    void normalisesServerAddresses();
    void readsEndpointsFromIors();
    void showsTheLiveTree();
    void remembersServers();
    void activatesThroughTheContextMenu();
    void filtersAndShowsIor();
    void pollsStatesInTheBackground();
    void deletesZombies();
    void unreachableServerIsReportedOnce();
    void stoppedManagerNeverBlocksTheGui();
    void stoppedComponentsNeverHideTheTree();

private:
    QString componentPath(const QString &instance) const;
    void refreshAndWait(NameServiceView &view);
    static int polledState(NameServiceView &view, const QString &path);

    LiveTest::LiveSystem m_live;
    QProcess *m_manager = nullptr;
    quint16 m_managerPort = 0;
    QTemporaryDir m_dir;
};

void TestOnlineNameService::initTestCase()
{
    Corba::Orb::setCallTimeout(2000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_managerPort = LiveTest::freePort();
    const QStringList arguments {"-d",
                                 "-o",
                                 QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(m_managerPort),
                                 "-o",
                                 "corba.nameservers=" + m_live.namingServer(),
                                 "-o",
                                 "naming.formats=rtmhost.host_cxt/%n.rtc",
                                 "-o",
                                 "manager.naming_formats=rtmhost.host_cxt/%n.mgr",
                                 "-o",
                                 "manager.components.precreate=ConsoleIn,ConsoleOut"};
    m_manager
        = m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error);
    QVERIFY2(m_manager, qPrintable(error));
}

QString TestOnlineNameService::componentPath(const QString &instance) const
{
    return QStringLiteral("/%1/rtmhost.host_cxt/%2.rtc").arg(m_live.namingServer(), instance);
}

void TestOnlineNameService::refreshAndWait(NameServiceView &view)
{
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    view.refresh();
    QVERIFY(refreshed.wait(15000));
}

// For QTRY_*: asks for a fresh poll (at most one per host is under way) and gives the state the
// view shows now. The manager answers activate() once the transition ran or after its transition
// timeout, so under load the state can change just after the call returned; one poll right after
// the call may still see the old one.
int TestOnlineNameService::polledState(NameServiceView &view, const QString &path)
{
    view.pollStates();
    return view.model()->indexOfPath(path).data(NameServiceModel::StateRole).toInt();
}

void TestOnlineNameService::normalisesServerAddresses_data()
{
    QTest::addColumn<QString>("address");
    QTest::addColumn<QString>("expected");
    QTest::newRow("host only") << "localhost"
                               << "localhost:2809";
    QTest::newRow("host and port") << "10.0.0.2:2999"
                                   << "10.0.0.2:2999";
    QTest::newRow("spaces") << "  myhost:1234 "
                            << "myhost:1234";
    QTest::newRow("bad port") << "host:abc"
                              << "";
    QTest::newRow("port out of range") << "host:70000"
                                       << "";
    QTest::newRow("no host") << ":2809"
                             << "";
    QTest::newRow("a path") << "host/ctx"
                            << "";
    QTest::newRow("empty") << ""
                           << "";
}

void TestOnlineNameService::normalisesServerAddresses()
{
    QFETCH(QString, address);
    QFETCH(QString, expected);
    QCOMPARE(NameServiceModel::normaliseServer(address), expected);
}

void TestOnlineNameService::readsEndpointsFromIors()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QVERIFY(view.addServer(m_live.namingServer()));
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    const QModelIndex index = view.model()->indexOfPath(componentPath("ConsoleIn0"));
    QVERIFY(index.isValid());
    const QString ior = index.data(NameServiceModel::IorRole).toString();
    QCOMPARE(Corba::iorEndpoint(ior), QStringLiteral("127.0.0.1:%1").arg(m_managerPort));
    QCOMPARE(Corba::iorEndpoint(QStringLiteral("IOR:0102")), QString());
    QCOMPARE(Corba::iorEndpoint(QStringLiteral("corbaloc::host:1/x")), QString());
    QCOMPARE(Corba::iorEndpoint(ior.left(60)), QString());
}

void TestOnlineNameService::showsTheLiveTree()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QAbstractItemModelTester tester(view.model(),
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    QAbstractItemModelTester filterTester(view.filterModel(),
                                          QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(view.addServer(m_live.namingServer()));
    QVERIFY(!view.addServer(m_live.namingServer())); // duplicates refused
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    refreshAndWait(view); // a second refresh replaces the subtree in place

    NameServiceModel *model = view.model();
    QCOMPARE(model->rowCount(), 1);
    const QModelIndex context
        = model->indexOfPath(QStringLiteral("/%1/rtmhost.host_cxt").arg(m_live.namingServer()));
    QVERIFY(context.isValid());
    QCOMPARE(NodeType(context.data(NameServiceModel::TypeRole).toInt()), NodeType::Context);
    const QModelIndex in = model->indexOfPath(componentPath("ConsoleIn0"));
    QVERIFY(in.isValid());
    QCOMPARE(in.parent(), context);
    QCOMPARE(NodeType(in.data(NameServiceModel::TypeRole).toInt()), NodeType::Component);
    QCOMPARE(in.siblingAtColumn(1).data().toString(), QStringLiteral("Inactive"));
    QVERIFY(in.data(NameServiceModel::IorRole).toString().startsWith("IOR:"));
    QVERIFY(!in.data(Qt::DecorationRole).value<QIcon>().isNull());
    QVERIFY(model->flags(in) & Qt::ItemIsDragEnabled);
    const QModelIndex manager = model->indexOfPath(
        QStringLiteral("/%1/rtmhost.host_cxt/manager.mgr").arg(m_live.namingServer()));
    QVERIFY(manager.isValid());
    QCOMPARE(NodeType(manager.data(NameServiceModel::TypeRole).toInt()), NodeType::Manager);
    QVERIFY(model->zombiePaths().isEmpty());
    // The manager lists its components again, with the same state.
    const QModelIndex managed
        = model->indexOfPath(QStringLiteral("/%1/rtmhost.host_cxt/manager.mgr/ConsoleIn0.rtc")
                                 .arg(m_live.namingServer()));
    QVERIFY(managed.isValid());
    QCOMPARE(managed.parent(), manager);
    QCOMPARE(managed.siblingAtColumn(1).data().toString(), QStringLiteral("Inactive"));

    std::unique_ptr<QMimeData> mime(model->mimeData({in}));
    QVERIFY(mime);
    QVERIFY(QString::fromUtf8(mime->data(NameServiceModel::componentMimeType()))
                .startsWith(componentPath("ConsoleIn0") + '\t' + "IOR:"));
}

void TestOnlineNameService::remembersServers()
{
    QSettings settings(m_dir.filePath("settings.ini"), QSettings::IniFormat);
    OnlineSession session;
    {
        NameServiceView view(&session, &settings);
        QVERIFY(view.addServer("otherhost"));
        QVERIFY(view.addServer("127.0.0.1:1"));
        view.removeServer("127.0.0.1:1");
    }
    NameServiceView again(&session, &settings);
    QCOMPARE(again.model()->servers(), QStringList {"otherhost:2809"});

    // Shown again, a remembered server's tree is read without a Refresh.
    {
        NameServiceView view(&session, &settings);
        view.removeServer(QStringLiteral("otherhost:2809"));
        QVERIFY(view.addServer(m_live.namingServer()));
    }
    NameServiceView reopened(&session, &settings);
    QSignalSpy listed(&reopened, &NameServiceView::serverListed);
    QVERIFY(!reopened.model()->indexOfPath(componentPath("ConsoleIn0")).isValid());
    reopened.show();
    QTRY_VERIFY_WITH_TIMEOUT(reopened.model()->indexOfPath(componentPath("ConsoleIn0")).isValid(),
                             15000);
    QCOMPARE(listed.size(), 1);
}

void TestOnlineNameService::activatesThroughTheContextMenu()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    view.addServer(m_live.namingServer());
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    const QString path = componentPath("ConsoleOut0");
    QModelIndex index = view.model()->indexOfPath(path);
    const QList<QAction *> actions = view.contextActions(index);
    QStringList names;
    for (QAction *action : actions)
        names.append(action->objectName());
    QCOMPARE(names,
             (QStringList {"actionActivate", "actionDeactivate", "actionReset", "actionExit",
                           "actionShowIor", "actionRefresh"}));
    QSignalSpy finished(&view, &NameServiceView::actionFinished);
    actions.at(0)->trigger();
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), path);
    QCOMPARE(finished.at(0).at(1).toString(), QString());
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, path), int(LifeCycleState::Active), 10000);
    QCOMPARE(view.model()->indexOfPath(path).siblingAtColumn(1).data().toString(),
             QStringLiteral("Active"));

    index = view.model()->indexOfPath(path);
    view.perform(RemoteAction::Deactivate, index);
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, path), int(LifeCycleState::Inactive), 10000);
    qDeleteAll(actions);

    const QModelIndex manager = view.model()->indexOfPath(
        QStringLiteral("/%1/rtmhost.host_cxt/manager.mgr").arg(m_live.namingServer()));
    const QList<QAction *> managerActions = view.contextActions(manager);
    QCOMPARE(managerActions.at(0)->objectName(), QStringLiteral("actionShutdown"));
    QCOMPARE(managerActions.at(1)->objectName(), QStringLiteral("actionRestart"));
    qDeleteAll(managerActions);
}

void TestOnlineNameService::filtersAndShowsIor()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    view.addServer(m_live.namingServer());
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    view.setFilterText("consolein");
    QSortFilterProxyModel *filter = view.filterModel();
    const QModelIndex server = filter->index(0, 0);
    const QModelIndex context = filter->index(0, 0, server);
    QStringList shown;
    for (int row = 0; row < filter->rowCount(context); ++row)
        shown.append(filter->index(row, 0, context).data().toString());
    // The manager stays because it lists ConsoleIn0 below itself.
    QCOMPARE(shown, (QStringList {"ConsoleIn0.rtc", "manager.mgr"}));
    view.setFilterText(QString());
    QVERIFY(filter->rowCount(filter->index(0, 0, filter->index(0, 0))) >= 3);

    const QModelIndex in = view.model()->indexOfPath(componentPath("ConsoleIn0"));
    QWidget *dialog = view.showIor(in);
    auto *text = dialog->findChild<QPlainTextEdit *>("iorText");
    QVERIFY(text);
    QCOMPARE(text->toPlainText(), in.data(NameServiceModel::IorRole).toString());
    dialog->close();
}

void TestOnlineNameService::pollsStatesInTheBackground()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QCOMPARE(view.pollInterval(), 1000);
    view.addServer(m_live.namingServer());
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    const QString path = componentPath("ConsoleIn0");
    QCOMPARE(view.model()->indexOfPath(path).data(NameServiceModel::StateRole).toInt(),
             int(LifeCycleState::Inactive));
    const QModelIndex in = view.model()->indexOfPath(path);
    const Corba::ComponentProxy proxy(in.data(NameServiceModel::IorRole).toString(), path);
    proxy.activate(); // from outside the view, so only a poll shows it
    QSignalSpy polled(&view, &NameServiceView::statesPolled);
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, path), int(LifeCycleState::Active), 10000);
    QVERIFY(!polled.isEmpty());
    const QModelIndex managed = view.model()->indexOfPath(
        QStringLiteral("/%1/rtmhost.host_cxt/manager.mgr/ConsoleIn0.rtc")
            .arg(m_live.namingServer()));
    QCOMPARE(managed.data(NameServiceModel::StateRole).toInt(), int(LifeCycleState::Active));
    proxy.deactivate();
}

void TestOnlineNameService::deletesZombies()
{
    QString error;
    QVERIFY2(
        m_live.startPeer({"ConsoleIn?instance_name=Alive0"}, &error, nullptr, "zombiehost", true),
        qPrintable(error));
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    view.addServer(m_live.namingServer());
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    const QStringList zombies = view.model()->zombiePaths(m_live.namingServer());
    QCOMPARE(zombies.size(), 2);
    QVERIFY(zombies.join(' ').contains("Ghost0.rtc"));
    const QModelIndex ghost = view.model()->indexOfPath(zombies.first());
    QVERIFY(!ghost.data(NameServiceModel::ReasonRole).toString().isEmpty());
    const QList<QAction *> actions = view.contextActions(ghost);
    QCOMPARE(actions.first()->objectName(), QStringLiteral("actionDeleteZombie"));
    qDeleteAll(actions);

    QSignalSpy finished(&view, &NameServiceView::actionFinished);
    view.deleteZombies();
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(view.model()->zombiePaths().isEmpty(), 10000);
    QVERIFY(view.model()
                ->indexOfPath(
                    QStringLiteral("/%1/zombiehost.host_cxt/Alive0.rtc").arg(m_live.namingServer()))
                .isValid());
}

void TestOnlineNameService::unreachableServerIsReportedOnce()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QSignalSpy problems(&view, &NameServiceView::problemReported);
    const QString dead = QStringLiteral("127.0.0.1:%1").arg(LiveTest::freePort());
    view.addServer(dead);
    QTRY_COMPARE_WITH_TIMEOUT(problems.size(), 1, 10000);
    view.refresh();
    view.refresh();
    QTRY_COMPARE_WITH_TIMEOUT(session.pendingCalls(), 0, 10000);
    QCOMPARE(problems.size(), 1);
    QVERIFY(problems.at(0).at(0).toString().contains(dead));
    const QModelIndex server = view.model()->index(0, 0);
    QVERIFY(view.model()->isUnreachable(server));
    QVERIFY(!(view.model()->flags(server) & Qt::ItemIsEnabled));
    QCOMPARE(server.siblingAtColumn(1).data().toString(), QStringLiteral("unreachable"));
}

void TestOnlineNameService::stoppedManagerNeverBlocksTheGui()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    view.addServer(m_live.namingServer());
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    const QString path = componentPath("ConsoleIn0");
    const QModelIndex in = view.model()->indexOfPath(path);
    const QString endpoint = in.data(NameServiceModel::EndpointRole).toString();
    QVERIFY(!endpoint.isEmpty());

    const LiveTest::StoppedProcess stopped(m_manager, 600, 2000);
    QVERIFY(stopped.isStopped());

    QSignalSpy problems(&view, &NameServiceView::problemReported);
    QSignalSpy finished(&view, &NameServiceView::actionFinished);
    LiveTest::StallMeter stalls;
    view.perform(RemoteAction::Activate, in);
    view.perform(RemoteAction::Reset, view.model()->indexOfPath(path));
    view.refresh();
    // Handed to the workers: none is answered before the GUI thread gets back to its event loop.
    QCOMPARE(session.pendingCalls(), 3);
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 15000);
    QTRY_COMPARE_WITH_TIMEOUT(session.pendingCalls(), 0, 30000);
    stalls.stop();
    QVERIFY2(stalls.worstNs() < Corba::Orb::callTimeout() * 1000000LL / 2,
             qPrintable(QStringLiteral("blocked for %1 ms").arg(stalls.worstMs())));
    QVERIFY(stalls.elapsedMs() >= 1000); // the calls did wait for their timeouts, off the GUI thread
    QVERIFY(!finished.at(0).at(1).toString().isEmpty());
    QCOMPARE(problems.size(), 1); // two failed calls, one report
    QVERIFY(problems.at(0).at(0).toString().contains(endpoint));
    QVERIFY(!view.model()->isHostReachable(endpoint));
    const QModelIndex greyed = view.model()->indexOfPath(path);
    QVERIFY(greyed.isValid());
    QVERIFY(!(view.model()->flags(greyed) & Qt::ItemIsEnabled));
    QCOMPARE(greyed.data(NameServiceModel::StateRole).toInt(), int(LifeCycleState::Unknown));
}

void TestOnlineNameService::stoppedComponentsNeverHideTheTree()
{
    // A second manager process with five components, bound under a host context of its own; it
    // is stopped (as a debugger or a hung machine would), the first one keeps answering.
    QString error;
    QProcess *hung = m_live.startHostManager(
        RTMANAGER_PATH, LiveTest::freePort(), "hunghost",
        {"manager.components.precreate=ConsoleIn,ConsoleIn,ConsoleIn,ConsoleOut,ConsoleOut"}, &error);
    QVERIFY2(hung, qPrintable(error));
    struct Stop
    {
        LiveTest::LiveSystem &live;
        QProcess *process;
        ~Stop() { live.stop(process); }
    } stop {m_live, hung};
    const QString hungPrefix = QStringLiteral("/%1/hunghost.host_cxt/").arg(m_live.namingServer());
    const QStringList hungPaths {hungPrefix + "ConsoleIn0.rtc", hungPrefix + "ConsoleIn1.rtc",
                                 hungPrefix + "ConsoleIn2.rtc", hungPrefix + "ConsoleOut0.rtc",
                                 hungPrefix + "ConsoleOut1.rtc"};

    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QSignalSpy listed(&view, &NameServiceView::serverListed);
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    view.addServer(m_live.namingServer());
    QVERIFY(refreshed.wait(15000));
    for (const QString &path : hungPaths)
        QVERIFY2(view.model()->indexOfPath(path).isValid(), qPrintable(path));

    LiveTest::StoppedProcess stopped(hung, 600, 2000);
    QVERIFY(stopped.isStopped());

    listed.clear();
    refreshed.clear();
    QElapsedTimer clock;
    clock.start();
    view.refresh();
    // The names come from the name server alone: every component is listed while the stopped
    // ones are still being asked (their check cannot end before a call timeout).
    QVERIFY(listed.wait(15000));
    QCOMPARE(refreshed.size(), 0);
    for (const QString &path : hungPaths + QStringList{componentPath("ConsoleIn0"), componentPath("ConsoleOut0")}) {
        const QModelIndex index = view.model()->indexOfPath(path);
        QVERIFY2(index.isValid(), qPrintable(path));
        QCOMPARE(NodeType(index.data(NameServiceModel::TypeRole).toInt()), NodeType::Component);
    }

    // Then the check: the stopped ones are marked, the others keep their states; the six silent
    // objects (five components and their manager) were asked at once, not one after the other
    // (which would take six call timeouts at least).
    QVERIFY(refreshed.wait(15000));
    const qint64 checked = clock.elapsed();
    QVERIFY2(checked < 4 * Corba::Orb::callTimeout(), qPrintable(QStringLiteral("%1 ms").arg(checked)));
    for (const QString &path : hungPaths) {
        const QModelIndex index = view.model()->indexOfPath(path);
        QVERIFY2(index.isValid(), qPrintable(path));
        QCOMPARE(NodeType(index.data(NameServiceModel::TypeRole).toInt()), NodeType::Component);
        QCOMPARE(index.siblingAtColumn(1).data().toString(), QStringLiteral("not answering"));
        QVERIFY(!(view.model()->flags(index) & Qt::ItemIsEnabled));
        QVERIFY(!index.data(Qt::ToolTipRole).toString().isEmpty());
    }
    if (!qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT").isEmpty()) {
        view.resize(520, 480);
        view.grab().save(qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT") + ".silent.png");
    }
    const QModelIndex answering = view.model()->indexOfPath(componentPath("ConsoleOut0"));
    QVERIFY(view.model()->flags(answering) & Qt::ItemIsEnabled);
    QVERIFY(answering.data(NameServiceModel::StateRole).toInt() != int(LifeCycleState::Unknown));
    // Listed below its manager (no reference), a component shows the state of the one of its name
    // bound beside that manager, not of the silent namesake in the other context.
    const QModelIndex managed = view.model()->indexOfPath(
        QStringLiteral("/%1/rtmhost.host_cxt/manager.mgr/ConsoleOut0.rtc").arg(m_live.namingServer()));
    QVERIFY(managed.isValid());
    QCOMPARE(managed.data(NameServiceModel::StateRole).toInt(), answering.data(NameServiceModel::StateRole).toInt());

    // Once the process goes on, the next refresh shows its components as they are.
    stopped.resume();
    refreshed.clear();
    view.refresh();
    QVERIFY(refreshed.wait(15000));
    const QModelIndex back = view.model()->indexOfPath(hungPaths.first());
    QVERIFY(view.model()->flags(back) & Qt::ItemIsEnabled);
    QVERIFY(back.data(NameServiceModel::StateRole).toInt() != int(LifeCycleState::Unknown));
}

QTEST_MAIN(TestOnlineNameService)
#include "tst_onlinenameservice.moc"
