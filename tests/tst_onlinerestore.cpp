// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "onlinesession.h"
#include "orb.h"
#include "portconnection.h"
#include "restoredialog.h"

#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

using namespace SystemEditor;

// The Restore dialog over the deployment engine, against a real rtmanager.
class TestOnlineRestore : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void showsTheMappingAndRestores();
    void untickedConnectorsAreNotConnected();
    void missingComponentsBlockTheRestore();

private:
    Profile::RtsProfile system(const QString &outInstance) const;
    Deploy::TargetOptions options() const;
    Corba::ComponentProxy component(const QString &instance) const;

    LiveTest::LiveSystem m_live;
};

void TestOnlineRestore::initTestCase()
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
        "naming.formats=rsthost.host_cxt/%n.rtc",
        "-o",
        "manager.naming_formats=rsthost.host_cxt/%n.mgr",
        "-o",
        "manager.components.precreate=ConsoleIn,ConsoleOut"};
    QVERIFY2(
        m_live.startProcess(QStringLiteral(RTMANAGER_PATH), arguments, "rtmanager ready", &error),
        qPrintable(error));
}

Profile::RtsProfile TestOnlineRestore::system(const QString &outInstance) const
{
    Profile::RtsProfile profile;
    profile.id = QStringLiteral("RTSystem:test:restore:1.0");
    auto addComponent = [&](const QString &type, const QString &instance, const QString &port) {
        Profile::RtsComponent c;
        c.id = QStringLiteral("RTC:AIST:example:%1:1.0").arg(type);
        c.instanceName = instance;
        Profile::RtsPort p;
        p.name = instance + '.' + port;
        c.dataPorts.append(p);
        profile.components.append(c);
    };
    addComponent("ConsoleIn", "ConsoleIn0", "out");
    addComponent("ConsoleOut", outInstance, "in");
    Profile::RtsDataPortConnector connector;
    connector.connectorId = QStringLiteral("restored-connector");
    connector.name = QStringLiteral("out_in");
    connector.dataType = QStringLiteral("RTC::TimedLong");
    connector.interfaceType = QStringLiteral("corba_cdr");
    connector.dataflowType = QStringLiteral("push");
    connector.subscriptionType = QStringLiteral("flush");
    connector.source.componentId = profile.components[0].id;
    connector.source.instanceName = "ConsoleIn0";
    connector.source.portName = "ConsoleIn0.out";
    connector.target.componentId = profile.components[1].id;
    connector.target.instanceName = outInstance;
    connector.target.portName = outInstance + ".in";
    profile.dataPortConnectors.append(connector);
    return profile;
}

Deploy::TargetOptions TestOnlineRestore::options() const
{
    Deploy::TargetOptions options;
    options.nameServers = QStringList {m_live.namingServer()};
    return options;
}

Corba::ComponentProxy TestOnlineRestore::component(const QString &instance) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/rsthost.host_cxt/%2.rtc").arg(m_live.namingServer(), instance));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestOnlineRestore::showsTheMappingAndRestores()
{
    OnlineSession session;
    RestoreDialog dialog(&session, system("ConsoleOut0"), options());
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.plan();
    QVERIFY(planned.wait(15000));
    QTableWidget *components = dialog.componentTable();
    QCOMPARE(components->rowCount(), 2);
    QCOMPARE(components->item(0, 0)->text(), QStringLiteral("ConsoleIn0"));
    QCOMPARE(components->item(0, 2)->text(), QStringLiteral("existing"));
    QVERIFY(components->item(1, 3)->text().endsWith("ConsoleOut0.rtc"));
    QCOMPARE(dialog.connectorTable()->rowCount(), 1);
    auto *restoreButton = dialog.findChild<QPushButton *>("restoreButton");
    QVERIFY(restoreButton->isEnabled());

    QSignalSpy restored(&dialog, &RestoreDialog::restored);
    QTest::mouseClick(restoreButton, Qt::LeftButton);
    QVERIFY(restored.wait(15000));
    QVERIFY2(restored.at(0).at(0).toBool(), qPrintable(dialog.report().toText()));
    QTRY_VERIFY(dialog.progressList()->count() > 0);
    bool connected = false;
    for (const Corba::ConnectorInfo &c : component("ConsoleIn0").port("out").connectors)
        connected = connected || c.id == QStringLiteral("restored-connector");
    QVERIFY(connected);
    Corba::PortConnection::disconnectAll(component("ConsoleIn0").port("out"), "test");
}

void TestOnlineRestore::untickedConnectorsAreNotConnected()
{
    OnlineSession session;
    RestoreDialog dialog(&session, system("ConsoleOut0"), options());
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.plan();
    QVERIFY(planned.wait(15000));
    dialog.connectorTable()->item(0, 3)->setCheckState(Qt::Unchecked);
    QSignalSpy restored(&dialog, &RestoreDialog::restored);
    dialog.restore();
    QVERIFY(restored.wait(15000));
    QVERIFY(restored.at(0).at(0).toBool());
    QVERIFY(component("ConsoleIn0").port("out").connectors.empty());
}

void TestOnlineRestore::missingComponentsBlockTheRestore()
{
    OnlineSession session;
    RestoreDialog dialog(&session, system("Absent0"), options());
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.plan();
    QVERIFY(planned.wait(15000));
    QCOMPARE(dialog.componentTable()->item(1, 2)->text(), QStringLiteral("missing"));
    QVERIFY(!dialog.findChild<QPushButton *>("restoreButton")->isEnabled());
    QVERIFY(dialog.findChild<QLabel *>("summaryLabel")->text().contains("Absent0"));
}

QTEST_MAIN(TestOnlineRestore)
#include "tst_onlinerestore.moc"
