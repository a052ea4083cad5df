// SPDX-License-Identifier: MIT
#include "livesystem.h"
#include "managerproxy.h"
#include "managerview.h"
#include "namingbrowser.h"
#include "onlinesession.h"
#include "orb.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QTreeWidget>

using namespace SystemEditor;

// The Manager view against real rtmanager processes.
class TestOnlineManager : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void showsFactoriesAndInstances();
    void buildsTheCreateArgument();
    void createsAndDeletesComponents();
    void reportsRefusedModules();
    void shutsTheManagerDown();

private:
    QProcess *startManager(const QString &host, QString *error);
    Corba::ManagerProxy manager(const QString &host) const;
    void load(ManagerView &view, const QString &host);
    void actAndWait(ManagerView &view, const std::function<void()> &action,
                    bool expectError = false);

    LiveTest::LiveSystem m_live;
};

void TestOnlineManager::initTestCase()
{
    Corba::Orb::setCallTimeout(5000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    QVERIFY2(startManager("mgrhost", &error), qPrintable(error));
}

QProcess *TestOnlineManager::startManager(const QString &host, QString *error)
{
    const QStringList arguments {
        "-d",
        "-o",
        QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(LiveTest::freePort()),
        "-o",
        "corba.nameservers=" + m_live.namingServer(),
        "-o",
        QStringLiteral("naming.formats=%1.host_cxt/%n.rtc").arg(host),
        "-o",
        QStringLiteral("manager.naming_formats=%1.host_cxt/%n.mgr").arg(host),
        "-o",
        "manager.components.precreate=ConsoleIn",
        "-o",
        QStringLiteral("manager.modules.load_path=") + MANAGER_TEST_MODULE_DIR};
    return m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", error);
}

Corba::ManagerProxy TestOnlineManager::manager(const QString &host) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), host));
    return Corba::ManagerProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestOnlineManager::load(ManagerView &view, const QString &host)
{
    QSignalSpy loaded(&view, &ManagerView::loaded);
    const Corba::ManagerProxy proxy = manager(host);
    view.setManager(proxy.path(), proxy.ior());
    QVERIFY(loaded.wait(10000));
}

void TestOnlineManager::actAndWait(ManagerView &view, const std::function<void()> &action,
                                   bool expectError)
{
    QSignalSpy finished(&view, &ManagerView::actionFinished);
    QSignalSpy loaded(&view, &ManagerView::loaded);
    action();
    QVERIFY(finished.wait(15000));
    QCOMPARE(finished.at(0).at(0).toString().isEmpty(), !expectError);
    if (!expectError)
        QVERIFY(loaded.wait(10000));
}

void TestOnlineManager::showsFactoriesAndInstances()
{
    OnlineSession session;
    ManagerView view(&session);
    load(view, "mgrhost");
    QVERIFY(view.types().contains("ConsoleIn"));
    QVERIFY(view.types().contains("ConfigSample"));
    QCOMPARE(view.targets().size(), 1 + view.snapshot().slaves.size());
    QVERIFY(view.snapshot().master);
    QTreeWidget *tree = view.tree();
    QStringList sections;
    for (int i = 0; i < tree->topLevelItemCount(); ++i)
        sections.append(tree->topLevelItem(i)->text(0));
    QCOMPARE(sections,
             (QStringList {"Slave managers", "Components", "Factories", "Loaded modules",
                           "Loadable modules", "Installed packages"}));
    QTreeWidgetItem *components = tree->topLevelItem(1);
    QCOMPARE(components->childCount(), 1);
    QCOMPARE(components->child(0)->text(0), QStringLiteral("ConsoleIn0"));
    QCOMPARE(components->child(0)->text(1), QStringLiteral("ConsoleIn"));
    auto *types = view.findChild<QComboBox *>("typeCombo");
    QCOMPARE(types->count(), view.types().size());

    // A loadable module shows the type it registers, which can be created (the manager loads it).
    QTreeWidgetItem *loadable = tree->topLevelItem(4);
    QCOMPARE(loadable->childCount(), 1);
    QCOMPARE(loadable->child(0)->text(0), QStringLiteral("ModuleCounter"));
    QCOMPARE(loadable->child(0)->text(1),
             MANAGER_TEST_MODULE_DIR + QStringLiteral("/ManagerTestModule.so"));
    QVERIFY(view.types().contains("ModuleCounter"));
    view.setCreateForm("ModuleCounter", 0, {{"instance_name", "Counted0"}});
    actAndWait(view, [&] { view.create(); });
    QVERIFY(manager("mgrhost").componentsByName("Counted0").size() == 1);
    QCOMPARE(view.tree()->topLevelItem(3)->childCount(), 1); // loaded modules
    actAndWait(view, [&] { view.deleteComponent("Counted0"); });
}

void TestOnlineManager::buildsTheCreateArgument()
{
    OnlineSession session;
    ManagerView view(&session);
    load(view, "mgrhost");
    view.setCreateForm("ConsoleOut", 0,
                       {{"instance_name", "Printer"}, {"exec_cxt.periodic.rate", "50"}});
    QCOMPARE(view.createArgument(),
             QStringLiteral("ConsoleOut?instance_name=Printer&exec_cxt.periodic.rate=50"));
    view.setCreateForm("ConsoleOut", 0, {{"instance_name", ""}});
    QCOMPARE(view.createArgument(), QStringLiteral("ConsoleOut"));
    auto *table = view.findChild<QTableWidget *>("parameterTable");
    QTest::mouseClick(view.findChild<QPushButton *>("addParameterButton"), Qt::LeftButton);
    QCOMPARE(table->rowCount(), 2);
    table->item(1, 0)->setText("conf.default.x");
    table->item(1, 1)->setText("1");
    QCOMPARE(view.createArgument(), QStringLiteral("ConsoleOut?conf.default.x=1"));
}

void TestOnlineManager::createsAndDeletesComponents()
{
    OnlineSession session;
    ManagerView view(&session);
    load(view, "mgrhost");
    view.setCreateForm("ConsoleOut", 0, {{"instance_name", "Made0"}});
    actAndWait(view, [&] {
        QTest::mouseClick(view.findChild<QPushButton *>("createButton"), Qt::LeftButton);
    });
    QVERIFY(manager("mgrhost").components().size() == 2);
    QTreeWidgetItem *components = view.tree()->topLevelItem(1);
    QCOMPARE(components->childCount(), 2);
    QTreeWidgetItem *made = nullptr;
    for (int i = 0; i < components->childCount(); ++i) {
        if (components->child(i)->text(0) == "Made0")
            made = components->child(i);
    }
    QVERIFY(made);
    view.tree()->setCurrentItem(made);
    actAndWait(view, [&] {
        QTest::mouseClick(view.findChild<QPushButton *>("deleteComponentButton"), Qt::LeftButton);
    });
    QCOMPARE(view.tree()->topLevelItem(1)->childCount(), 1);
    QCOMPARE(manager("mgrhost").components().size(), 1);

    view.setCreateForm("NoSuchType", 0, {});
    actAndWait(
        view, [&] { view.create(); }, true);
}

void TestOnlineManager::reportsRefusedModules()
{
    OnlineSession session;
    ManagerView view(&session);
    load(view, "mgrhost");
    actAndWait(
        view, [&] { view.loadModule("/nonexistent/Module.so", "ModuleInit"); }, true);
    QVERIFY(!view.findChild<QLabel *>("statusLabel")->text().isEmpty());
}

void TestOnlineManager::shutsTheManagerDown()
{
    QString error;
    QProcess *process = startManager("downhost", &error);
    QVERIFY2(process, qPrintable(error));
    OnlineSession session;
    ManagerView view(&session);
    load(view, "downhost");
    QSignalSpy finished(&view, &ManagerView::actionFinished);
    QTest::mouseClick(view.findChild<QPushButton *>("shutdownButton"), Qt::LeftButton);
    QVERIFY(finished.wait(15000));
    QTRY_COMPARE_WITH_TIMEOUT(process->state(), QProcess::NotRunning, 15000);
}

QTEST_MAIN(TestOnlineManager)
#include "tst_onlinemanager.moc"
