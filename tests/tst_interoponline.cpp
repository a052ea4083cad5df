// SPDX-License-Identifier: MIT
// The online System Editor's Name Service view and its worker session against OpenRTM-aist 2.x:
// its example programs and an rtcd2 master with a component in a slave, next to rtmanager, on one
// name server. The tree, the states the view polls and the actions it performs on OpenRTM-aist's
// components are checked as tst_onlinenameservice checks them against rtmanager.
//
// Needs the prefix of an OpenRTM-aist installation (CMake cache variable RTSTUDIO_OPENRTM_PREFIX,
// ctest label "interop"); without one the test is skipped.
#include "livesystem.h"
#include "managerproxy.h"
#include "managerview.h"
#include "namingbrowser.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinesession.h"
#include "orb.h"
#include "rtctlrunner.h"

#include <QAction>
#include <QFile>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using namespace SystemEditor;
using Corba::LifeCycleState;
using Corba::NodeType;

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);
const QString examples = openRtmPrefix + "/share/openrtm-2.1/components/c++/examples/";

} // namespace

class TestInteropOnline : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void showsOpenRtmInTheTree();
    void pollsAndDrivesOpenRtmStates();
    void managerViewDrivesRtcd();

private:
    QString path(const QString &relative) const
    {
        return "/" + m_live.namingServer() + "/" + relative;
    }
    static int polledState(NameServiceView &view, const QString &path);
    void refreshed(NameServiceView &view);

    LiveTest::LiveSystem m_live;
    QTemporaryDir m_work;
    QProcess *m_master = nullptr;
};

int TestInteropOnline::polledState(NameServiceView &view, const QString &path)
{
    view.pollStates();
    return view.model()->indexOfPath(path).data(NameServiceModel::StateRole).toInt();
}

void TestInteropOnline::refreshed(NameServiceView &view)
{
    QSignalSpy spy(&view, &NameServiceView::serverRefreshed);
    QVERIFY(view.addServer(m_live.namingServer()));
    QVERIFY(spy.wait(15000));
}

void TestInteropOnline::initTestCase()
{
    if (openRtmPrefix.isEmpty() || !QFile::exists(openRtmPrefix + "/bin/rtcd2"))
        QSKIP("skipped: no OpenRTM-aist (RTSTUDIO_OPENRTM_PREFIX unset or without bin/rtcd2)");
    LiveTest::useOpenRtm(openRtmPrefix);
    Corba::Orb::setCallTimeout(5000);
    QVERIFY(m_work.isValid());
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QString server = m_live.namingServer();
    QStringList arguments;
    for (const QString &option :
         {"corba.nameservers:" + server, QStringLiteral("corba.endpoints:127.0.0.1:"),
          QStringLiteral("naming.formats:openrtm.host_cxt/%n.rtc"),
          QStringLiteral("manager.corba_servant:NO"), QStringLiteral("logger.enable:NO"),
          QStringLiteral("exec_cxt.periodic.rate:20")})
        arguments << "-o" << option;
    QVERIFY2(m_live.startProcess(examples + "SeqOutComp", arguments, QString(), &error, 0),
             qPrintable(error));
    // An rtcd2 master; the component it creates lives in a slave process.
    const quint16 masterPort = LiveTest::freePort();
    QVERIFY2(m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(), "ours",
                                     {"manager.components.precreate=SeqIn"}, &error),
             qPrintable(error));
    m_master = m_live.startRtcdMaster(openRtmPrefix, m_work.filePath("master.conf"), masterPort, "rtcd",
                                      {"manager.modules.load_path: " + examples + "rtc",
                                       "manager.modules.preload: ConsoleOut.so"},
                                      &error);
    QVERIFY2(m_master, qPrintable(error));
    const QString cwd = "/" + server;
    QTRY_VERIFY_WITH_TIMEOUT(runRtctlAt(cwd, {"cat", "openrtm.host_cxt/SeqOut0.rtc"}).code == 0,
                             30000);
    QTRY_VERIFY_WITH_TIMEOUT(runRtctlAt(cwd, {"cat", "rtcd.host_cxt/manager.mgr"}).code == 0,
                             30000);
    const RtctlResult created
        = runRtctlAt(cwd,
                     {"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(masterPort), "create",
                      "ConsoleOut?instance_name=Made0&manager_name=onlineslave"});
    QVERIFY2(created.code == 0, qPrintable(created.err));
}

void TestInteropOnline::cleanupTestCase()
{
    m_master = nullptr;
    m_live.stopAll();
}

void TestInteropOnline::showsOpenRtmInTheTree()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    refreshed(view);
    NameServiceModel *model = view.model();
    const QModelIndex seqOut = model->indexOfPath(path("openrtm.host_cxt/SeqOut0.rtc"));
    QVERIFY(seqOut.isValid());
    QCOMPARE(NodeType(seqOut.data(NameServiceModel::TypeRole).toInt()), NodeType::Component);
    QCOMPARE(seqOut.siblingAtColumn(1).data().toString(), QStringLiteral("Inactive"));
    QVERIFY(seqOut.data(NameServiceModel::IorRole).toString().startsWith("IOR:"));
    QCOMPARE(NodeType(model->indexOfPath(path("ours.host_cxt/SeqIn0.rtc"))
                          .data(NameServiceModel::TypeRole)
                          .toInt()),
             NodeType::Component);
    // rtcd2's master, the component its slave holds listed below it and bound by name.
    const QModelIndex master = model->indexOfPath(path("rtcd.host_cxt/manager.mgr"));
    QVERIFY(master.isValid());
    QCOMPARE(NodeType(master.data(NameServiceModel::TypeRole).toInt()), NodeType::Manager);
    const QModelIndex managed = model->indexOfPath(path("rtcd.host_cxt/manager.mgr/Made0.rtc"));
    QVERIFY(managed.isValid());
    QCOMPARE(managed.parent(), master);
    QCOMPARE(managed.siblingAtColumn(1).data().toString(), QStringLiteral("Inactive"));
    QVERIFY(model->indexOfPath(path("rtcd.host_cxt/Made0.rtc")).isValid());
    QVERIFY(model->zombiePaths().isEmpty());
    // The path the tree shows below the master names the component for rtctl too.
    const RtctlResult cat
        = runRtctlAt("/" + m_live.namingServer(), {"cat", "rtcd.host_cxt/manager.mgr/Made0.rtc"});
    QVERIFY2(cat.code == 0 && cat.out.contains("Made0"), qPrintable(cat.out + cat.err));
}

void TestInteropOnline::pollsAndDrivesOpenRtmStates()
{
    OnlineSession session;
    NameServiceView view(&session, nullptr);
    refreshed(view);
    // Through the view's own action.
    const QString seqOut = path("openrtm.host_cxt/SeqOut0.rtc");
    const QList<QAction *> actions = view.contextActions(view.model()->indexOfPath(seqOut));
    QVERIFY(!actions.isEmpty());
    QCOMPARE(actions.at(0)->objectName(), QStringLiteral("actionActivate"));
    QSignalSpy finished(&view, &NameServiceView::actionFinished);
    actions.at(0)->trigger();
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), seqOut);
    QCOMPARE(finished.at(0).at(1).toString(), QString());
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, seqOut), int(LifeCycleState::Active), 10000);
    view.perform(RemoteAction::Deactivate, view.model()->indexOfPath(seqOut));
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, seqOut), int(LifeCycleState::Inactive), 10000);
    qDeleteAll(actions);

    // From outside (rtctl), on the component in rtcd2's slave: only a poll shows it.
    const QString made = path("rtcd.host_cxt/Made0.rtc");
    QCOMPARE(runRtctlAt("/" + m_live.namingServer(), {"act", "rtcd.host_cxt/Made0.rtc"}).code, 0);
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, made), int(LifeCycleState::Active), 10000);
    QCOMPARE(view.model()
                 ->indexOfPath(path("rtcd.host_cxt/manager.mgr/Made0.rtc"))
                 .data(NameServiceModel::StateRole)
                 .toInt(),
             int(LifeCycleState::Active));
    QCOMPARE(runRtctlAt("/" + m_live.namingServer(), {"deact", "rtcd.host_cxt/Made0.rtc"}).code, 0);
    QTRY_COMPARE_WITH_TIMEOUT(polledState(view, made), int(LifeCycleState::Inactive), 10000);
}

// The Manager view on rtcd2's master: a module loaded by its file, a component created (rtcd2's
// master makes it in a slave, listed among the master's components) and deleted again.
void TestInteropOnline::managerViewDrivesRtcd()
{
    const auto master = Corba::RtPath::parse(path("rtcd.host_cxt/manager.mgr"));
    QVERIFY(master);
    OnlineSession session;
    ManagerView view(&session);
    auto actAndWait = [&view](const std::function<void()> &action) {
        QSignalSpy finished(&view, &ManagerView::actionFinished);
        QSignalSpy loaded(&view, &ManagerView::loaded);
        action();
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.at(0).at(0).toString(), QString());
        QVERIFY(loaded.wait(10000));
    };
    {
        QSignalSpy loaded(&view, &ManagerView::loaded);
        view.setManager(master->toString(), Corba::NamingBrowser::resolve(*master));
        QVERIFY(loaded.wait(10000));
    }
    QVERIFY(view.snapshot().master);
    const auto factoryTypes = [&view] {
        QStringList types;
        for (const Corba::Properties &factory : view.snapshot().factories)
            types << Corba::propertyValue(factory, "implementation_id");
        return types;
    };
    QVERIFY(!factoryTypes().contains("ConfigSample"));
    // rtcd2 lists its loadable modules by the types they register; the view offers those too.
    QStringList loadable;
    QTreeWidgetItem *modules = view.tree()->topLevelItem(4);
    for (int i = 0; i < modules->childCount(); ++i)
        loadable << modules->child(i)->text(0);
    QVERIFY2(loadable.contains("ConfigSample") && loadable.contains("SeqIn"),
             qPrintable(loadable.join(' ')));
    QVERIFY(view.types().contains("ConfigSample"));
    actAndWait([&] { view.loadModule(examples + "rtc/ConfigSample.so", "ConfigSampleInit"); });
    QVERIFY2(factoryTypes().contains("ConfigSample"), qPrintable(factoryTypes().join(' ')));

    view.setCreateForm("ConfigSample", 0, {{"instance_name", "ViewMade0"}});
    actAndWait([&] {
        QTest::mouseClick(view.findChild<QPushButton *>("createButton"), Qt::LeftButton);
    });
    QTRY_VERIFY_WITH_TIMEOUT(
        runRtctlAt("/" + m_live.namingServer(), {"cat", "rtcd.host_cxt/ViewMade0.rtc"}).code == 0,
        10000);
    QTreeWidgetItem *made = nullptr;
    QTreeWidgetItem *components = view.tree()->topLevelItem(1);
    for (int i = 0; i < components->childCount(); ++i) {
        if (components->child(i)->text(0) == "ViewMade0")
            made = components->child(i);
    }
    QVERIFY(made);
    view.tree()->setCurrentItem(made);
    actAndWait([&] {
        QTest::mouseClick(view.findChild<QPushButton *>("deleteComponentButton"), Qt::LeftButton);
    });
    QTRY_VERIFY_WITH_TIMEOUT(
        runRtctlAt("/" + m_live.namingServer(), {"cat", "rtcd.host_cxt/ViewMade0.rtc"}).code != 0,
        10000);
}

QTEST_MAIN(TestInteropOnline)
#include "tst_interoponline.moc"
