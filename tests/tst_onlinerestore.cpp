// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "corbaerror.h"
#include "driftview.h"
#include "livesystem.h"
#include "mainwindow.h"
#include "managerproxy.h"
#include "nameserviceview.h"
#include "namingbrowser.h"
#include "onlinedocks.h"
#include "onlinesession.h"
#include "orb.h"
#include "portconnection.h"
#include "profileio.h"
#include "restoredialog.h"
#include "rtsdocument.h"
#include "rtsxml.h"
#include "stallmeter.h"
#include "stoppedprocess.h"
#include "uilanguage.h"

#include <QCheckBox>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScopeGuard>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QTreeWidget>

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
    void japaneseDialogShowsTheEnginesReasons();
    void createsTheExampleFromNothing();
    void driftShowsAChangedConfigurationValue();
    void stoppedManagerMidRestoreRollsBack();
    void failedRestoreFromTheWindowLeavesTheDocument();

private:
    Profile::RtsProfile system(const QString &outInstance) const;
    Deploy::TargetOptions options() const;
    Corba::ComponentProxy component(const QString &instance) const;

    QTemporaryDir m_settings;
    LiveTest::LiveSystem m_live;
};

void TestOnlineRestore::initTestCase()
{
    // The main window keeps its settings (name servers, layout) in a folder of the test's own.
    QVERIFY(m_settings.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_onlinerestore"));
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
        "manager.components.precreate=ConsoleIn,ConsoleOut,ConfigSample"};
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error),
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
    auto *busy = dialog.findChild<QProgressBar *>("restoreBusy");
    auto *cancel = dialog.findChild<QPushButton *>("cancelRestoreButton");
    QVERIFY(busy && cancel);
    QTest::mouseClick(restoreButton, Qt::LeftButton);
    // While it runs: a busy bar and Cancel; afterwards neither.
    QVERIFY(!busy->isHidden() && !cancel->isHidden() && cancel->isEnabled());
    QVERIFY(restored.wait(15000));
    QVERIFY2(restored.at(0).at(0).toBool(), qPrintable(dialog.report().toText()));
    QVERIFY(busy->isHidden() && cancel->isHidden());
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

void TestOnlineRestore::japaneseDialogShowsTheEnginesReasons()
{
    // The engine words its reasons in the GUI's language (rtctl installs no translator).
    QTranslator japanese;
    QVERIFY(japanese.load(Studio::UiLanguage::catalogue(QStringLiteral("ja"))));
    QVERIFY(QCoreApplication::installTranslator(&japanese));
    const auto english
        = qScopeGuard([&japanese] { QCoreApplication::removeTranslator(&japanese); });
    OnlineSession session;
    RestoreDialog dialog(&session, system("Absent0"), options());
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.plan();
    QVERIFY(planned.wait(15000));
    const QString reason = dialog.componentTable()->item(1, RestoreDialog::PathColumn)->text();
    QVERIFY2(reason.contains(QStringLiteral("Absent0")), qPrintable(reason));
    QVERIFY2(!reason.contains(QStringLiteral("no live component")), qPrintable(reason));
    QCOMPARE(reason, QStringLiteral("稼働中のコンポーネント Absent0 が見つかりません"));

    QTest::mouseClick(dialog.findChild<QPushButton *>("dryRunButton"), Qt::LeftButton);
    const QList<QListWidgetItem *> lines
        = dialog.progressList()->findItems(QStringLiteral("Absent0"), Qt::MatchContains);
    QVERIFY(!lines.isEmpty());
    for (const QListWidgetItem *line : lines)
        QVERIFY2(!line->text().contains(QStringLiteral("missing"))
                     && !line->text().contains(QStringLiteral("component")),
                 qPrintable(line->text()));
}

void TestOnlineRestore::createsTheExampleFromNothing()
{
    // A name server and manager of its own, so that nothing of the example runs yet.
    LiveTest::LiveSystem fresh;
    QString error;
    QVERIFY2(fresh.startNameServer(&error), qPrintable(error));
    const quint16 managerPort = LiveTest::freePort();
    QVERIFY2(fresh.startProcess(RTMANAGER_PATH,
                                {"-d", "-o",
                                 QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(managerPort),
                                 "-o", "corba.nameservers=" + fresh.namingServer(), "-o",
                                 "naming.formats=newhost.host_cxt/%n.rtc", "-o",
                                 "manager.naming_formats=newhost.host_cxt/%n.mgr"},
                                "rtmanager ready", &error),
             qPrintable(error));
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(
        RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml"),
        &diagnostics);
    QVERIFY(loaded && loaded->rts);
    Deploy::TargetOptions target;
    target.nameServers = {fresh.namingServer()};
    OnlineSession session;
    RestoreDialog dialog(&session, *loaded->rts, target);
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.plan();
    QVERIFY(planned.wait(15000));
    QTableWidget *components = dialog.componentTable();
    QCOMPARE(components->item(0, RestoreDialog::MappingColumn)->text(), QStringLiteral("missing"));
    auto *restoreButton = dialog.findChild<QPushButton *>("restoreButton");
    QVERIFY(!restoreButton->isEnabled());

    // Ticking "create missing" with the manager plans both components as created.
    const QString manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort);
    dialog.setManagers({manager});
    dialog.findChild<QCheckBox *>("createCheck")->setChecked(true);
    QVERIFY(planned.wait(15000));
    QCOMPARE(components->item(0, RestoreDialog::MappingColumn)->text(), QStringLiteral("create"));
    QCOMPARE(components->item(1, RestoreDialog::MappingColumn)->text(), QStringLiteral("create"));
    QVERIFY(components->item(0, RestoreDialog::ManagerColumn)->flags() & Qt::ItemIsEditable);
    QVERIFY(restoreButton->isEnabled());

    QTest::mouseClick(dialog.findChild<QPushButton *>("dryRunButton"), Qt::LeftButton);
    QVERIFY(!dialog.progressList()
                 ->findItems("component ConsoleIn0 create", Qt::MatchContains)
                 .isEmpty());

    QSignalSpy restored(&dialog, &RestoreDialog::restored);
    QTest::mouseClick(restoreButton, Qt::LeftButton);
    QVERIFY(restored.wait(20000));
    QVERIFY2(restored.at(0).at(0).toBool(), qPrintable(dialog.report().toText()));
    QVERIFY(!dialog.progressList()->findItems("create ConsoleIn0", Qt::MatchContains).isEmpty());
    for (const char *instance : {"ConsoleIn0", "ConsoleOut0"}) {
        const auto path = Corba::RtPath::parse(
            QStringLiteral("/%1/newhost.host_cxt/%2.rtc").arg(fresh.namingServer(), instance));
        const Corba::ComponentProxy proxy(Corba::NamingBrowser::resolve(*path), path->toString());
        QCOMPARE(proxy.profile().instanceName, QString::fromLatin1(instance));
    }
    if (!qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT").isEmpty()) {
        dialog.resize(1000, 640);
        dialog.grab().save(qEnvironmentVariable("RTSTUDIO_ONLINE_SCREENSHOT") + ".restore.png");
    }

    // Planned again, the created components are found running.
    dialog.setCreateMissing(true, manager);
    QVERIFY(planned.wait(15000));
    QCOMPARE(components->item(0, RestoreDialog::MappingColumn)->text(), QStringLiteral("existing"));
}

void TestOnlineRestore::driftShowsAChangedConfigurationValue()
{
    Profile::RtsProfile profile = system("ConsoleOut0");
    const Corba::ComponentProxy in = component("ConsoleIn0");
    OnlineSession session;
    DriftView view(&session, profile, options(), QStringLiteral("system.xml"));
    QSignalSpy refreshed(&view, &DriftView::refreshed);
    view.refresh();
    QVERIFY(refreshed.wait(15000));
    // Not connected live: the saved connector is missing.
    bool missingConnector = false;
    for (const Deploy::DriftItem &item : view.items())
        missingConnector = missingConnector
            || (item.kind == Deploy::DriftItem::Kind::MissingConnector
                && item.subject == QStringLiteral("restored-connector"));
    QVERIFY(missingConnector);
    QVERIFY(view.tree()->topLevelItemCount() > 0);

    // The file holds the live value of a parameter; then the live value changes.
    const Corba::ComponentProxy sample = component("ConfigSample0");
    const QString before = sample.parameter("default", "int_param0");
    Profile::RtsComponent saved;
    saved.id = QStringLiteral("RTC:AIST:example:ConfigSample:1.0");
    saved.instanceName = QStringLiteral("ConfigSample0");
    Profile::RtsConfigurationSet set;
    set.id = QStringLiteral("default");
    Profile::RtsConfigurationData data;
    data.name = QStringLiteral("int_param0");
    data.data = before;
    set.data.append(data);
    saved.configurationSets.append(set);
    profile.components.append(saved);
    DriftView changed(&session, profile, options(), QStringLiteral("system.xml"));
    QSignalSpy changedRefreshed(&changed, &DriftView::refreshed);
    changed.refresh();
    QVERIFY(changedRefreshed.wait(15000));
    const QString subject = QStringLiteral("ConfigSample0.default.int_param0");
    QVERIFY(changed.tree()->findItems(subject, Qt::MatchRecursive).isEmpty());

    const QString after = before == QStringLiteral("5") ? QStringLiteral("6") : QStringLiteral("5");
    sample.setParameter("default", "int_param0", after);
    QTest::mouseClick(changed.findChild<QPushButton *>("refreshButton"), Qt::LeftButton);
    QVERIFY(changedRefreshed.wait(15000));
    const auto found = changed.tree()->findItems(subject, Qt::MatchRecursive);
    QCOMPARE(found.size(), 1);
    QCOMPARE(found.first()->text(1), before);
    QCOMPARE(found.first()->text(2), after);
    QVERIFY(changed.summary().contains("difference"));
    sample.setParameter("default", "int_param0", before);
}

namespace {

/// Two managers: a restore creates ConsoleIn0 through the first (makerhost), then connects it to
/// ConsoleOut0, which runs in the second (stophost) — the one a test stops once the plan is made.
struct TwoManagers
{
    LiveTest::LiveSystem live;
    quint16 creatorPort = 0;
    quint16 hostPort = 0;
    QProcess *host = nullptr;
    QString creator;

    bool start(QString *error)
    {
        if (!live.startNameServer(error))
            return false;
        creatorPort = LiveTest::freePort();
        if (!live.startHostManager(RTMANAGER_PATH, creatorPort, "makerhost", {}, error))
            return false;
        hostPort = LiveTest::freePort();
        host = live.startHostManager(RTMANAGER_PATH, hostPort, "stophost",
                                     {"manager.components.precreate=ConsoleOut"}, error);
        creator = QStringLiteral("corbaloc::127.0.0.1:%1").arg(creatorPort);
        return host != nullptr;
    }

    /// Runs a planned restore of `dialog` with the second manager stopped; the report, or why not.
    bool restoreWhileStopped(RestoreDialog &dialog, qint64 *worstStallMs, QString *report)
    {
        const LiveTest::StoppedProcess stopped(host, 800, 3000);
        if (!stopped.isStopped())
            return false;
        LiveTest::StallMeter stalls;
        QSignalSpy restored(&dialog, &RestoreDialog::restored);
        QTest::mouseClick(dialog.findChild<QPushButton *>("restoreButton"), Qt::LeftButton);
        if (!restored.wait(30000))
            return false;
        stalls.stop();
        *worstStallMs = stalls.worstMs();
        *report = dialog.report().toText();
        return !restored.at(0).at(0).toBool();
    }

    /// ConsoleIn0, created by the restore, was removed again.
    bool rolledBack() const
    {
        const auto created = Corba::RtPath::parse(
            QStringLiteral("/%1/makerhost.host_cxt/ConsoleIn0.rtc").arg(live.namingServer()));
        bool gone = false;
        try {
            Corba::NamingBrowser::resolve(*created);
        } catch (const Corba::Error &e) {
            gone = e.kind() == Corba::Error::Kind::NotFound;
        }
        const auto manager = Corba::RtPath::parse(creator);
        return gone && Corba::ManagerProxy(manager->corbaloc, creator).componentProfiles().empty();
    }
};

} // namespace

void TestOnlineRestore::stoppedManagerMidRestoreRollsBack()
{
    TwoManagers managers;
    QString error;
    QVERIFY2(managers.start(&error), qPrintable(error));

    Deploy::TargetOptions target;
    target.nameServers = {managers.live.namingServer()};
    const Profile::RtsProfile profile = system("ConsoleOut0");
    OnlineSession session;
    RestoreDialog dialog(&session, profile, target);
    QSignalSpy planned(&dialog, &RestoreDialog::planned);
    dialog.setManagers({managers.creator});
    dialog.setCreateMissing(true, managers.creator);
    QVERIFY(planned.wait(15000));
    QTableWidget *components = dialog.componentTable();
    QCOMPARE(components->item(0, RestoreDialog::MappingColumn)->text(), QStringLiteral("create"));
    QCOMPARE(components->item(1, RestoreDialog::MappingColumn)->text(), QStringLiteral("existing"));

    qint64 worst = 0;
    QString report;
    QVERIFY2(managers.restoreWhileStopped(dialog, &worst, &report), qPrintable(report));
    // The event loop never waited on the stopped manager.
    QVERIFY2(worst < 100, qPrintable(QStringLiteral("blocked for %1 ms").arg(worst)));
    // The report names what stopped answering: the component and the process that hosts it.
    QVERIFY2(report.contains(QStringLiteral("ConsoleOut0")), qPrintable(report));
    QVERIFY2(report.contains(QStringLiteral("127.0.0.1:%1").arg(managers.hostPort)), qPrintable(report));
    QVERIFY2(report.contains(QStringLiteral("ConsoleIn0")), qPrintable(report));
    QVERIFY2(managers.rolledBack(), "ConsoleIn0 is still there after the rollback");
}

void TestOnlineRestore::failedRestoreFromTheWindowLeavesTheDocument()
{
    // The same failure started as a user does: the system open in the main window, Online →
    // Restore System on Live Managers, the name server in the Name Service view.
    TwoManagers managers;
    QString error;
    QVERIFY2(managers.start(&error), qPrintable(error));
    QTemporaryDir dir;
    const QString file = dir.filePath("restore.xml");
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(Profile::writeRtsXml(system("ConsoleOut0")));
    out.close();
    QFile saved(file);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QByteArray before = saved.readAll();

    Studio::MainWindow window;
    window.show();
    QVERIFY(window.openFiles({file}));
    auto *document = qobject_cast<Studio::RtsDocument *>(window.activeDocument());
    QVERIFY(document);
    const Profile::RtsProfile opened = document->profile();
    QVERIFY(window.onlineDocks()->nameService()->addServer(managers.live.namingServer()));
    RestoreDialog *dialog = window.onlineDocks()->openRestore(document->profile());
    dialog->setManagers({managers.creator});
    dialog->setCreateMissing(true, managers.creator);
    // The dialog plans when it opens and again for the manager: wait for the plan that creates.
    QTRY_VERIFY_WITH_TIMEOUT(dialog->componentTable()->rowCount() == 2
                                 && dialog->componentTable()->item(0, RestoreDialog::MappingColumn)->text() == "create"
                                 && dialog->findChild<QPushButton *>("restoreButton")->isEnabled(),
                             20000);

    qint64 worst = 0;
    QString report;
    QVERIFY2(managers.restoreWhileStopped(*dialog, &worst, &report), qPrintable(report));
    QVERIFY2(worst < 100, qPrintable(QStringLiteral("blocked for %1 ms").arg(worst)));
    QVERIFY2(managers.rolledBack(), "ConsoleIn0 is still there after the rollback");
    // The document is as it was opened: not modified, the same profile, the file untouched.
    QVERIFY(!document->isModified());
    QVERIFY(document->profile() == opened);
    QVERIFY(saved.seek(0));
    QCOMPARE(saved.readAll(), before);
    dialog->close();
}

QTEST_MAIN(TestOnlineRestore)
#include "tst_onlinerestore.moc"
