// SPDX-License-Identifier: MIT
// rtctl deploy and undeploy: install, then launch, in one transaction. The tour's Doubler is
// generated, given its onExecute, built against this build tree's SDK, packaged and published in
// a repository signed with a throwaway key; a manager whose load path and package store hold no
// Doubler deploys a system of a counter, the Doubler and a printer from that repository: the
// package is installed, the system restored and started, and doubled counts arrive. A dry run
// changes nothing; undeploy --uninstall leaves the store empty; a type no repository provides, an
// unsigned repository and a connector that cannot be made each fail with a message naming what
// failed, and leave no component and no package behind. Across two hosts simulated with network
// namespaces, with the repository served over HTTP by busybox's web server on a third, the
// Doubler is installed only where the system places it and data flows from host to host. With
// --watch, killing the manager that runs the Doubler moves it to the other one, and data flows
// again.
#include "componentstatus.h"
#include "healer.h"
#include "livesystem.h"
#include "managerproxy.h"
#include "managerview.h"
#include "mainwindow.h"
#include "nameserviceview.h"
#include "onlinedocks.h"
#include "onlinediagram.h"
#include "planview.h"
#include "rtsdocument.h"
#include "rtseditor.h"
#include "onlineservice.h"
#include "onlinesession.h"
#include "profileio.h"
#include "restoredialog.h"
#include "rtctlrunner.h"
#include "rtsprofile.h"
#include "sdkproject.h"
#include "simulatedhosts.h"
#include "tst_deploysupport.h"

#include <QAction>
#include <QCheckBox>
#include <QDirIterator>
#include <QScopeGuard>
#include <QSettings>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTreeWidget>
#include <QTcpSocket>
#include <QtTest>

namespace {

const QString doublerProfile = RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/tour/Doubler.xml");
const QString package = QStringLiteral("rtc-rtstudio-tour-doubler");
const QStringList systemInstances {QStringLiteral("Count0"), QStringLiteral("Doubler0"),
                                   QStringLiteral("Show0")};

const SdkTest::UserEdit doubling {"src/Doubler.cpp",
                                  "Doubler::onExecute(RTC::UniqueId /*ec_id*/)\n{\n  return RTC::RTC_OK;\n}",
                                  "Doubler::onExecute(RTC::UniqueId /*ec_id*/)\n{\n"
                                  "  while (m_inIn.isNew()) {\n"
                                  "    m_inIn.read();\n"
                                  "    m_out.data = 2 * m_in.data;\n"
                                  "    setTimestamp(m_out);\n"
                                  "    m_outOut.write();\n"
                                  "  }\n"
                                  "  return RTC::RTC_OK;\n}"};

/// Every file below @p root, relative to it: what a failed deploy must leave as it was.
QStringList filesBelow(const QString &root)
{
    QStringList files;
    QDirIterator it(root, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext())
        files << it.next().mid(root.size());
    files.sort();
    return files;
}


} // namespace

/// Hosts A and B simulated with network namespaces, each with omniNames on 2809 and an rtmanager
/// on 2810 whose package store starts empty, and a third host serving the repository over HTTP
/// with busybox's web server, as any static web server would.
struct SimulatedNodes
{
    LiveTest::SimulatedHosts hosts;
    std::map<QString, std::unique_ptr<LiveTest::LiveSystem>> live;
    std::map<QString, QProcess *> managers;
    std::unique_ptr<LiveTest::LiveSystem> web;
    QString repositoryUrl;

    QString node(const QString &host) const { return QStringLiteral("corbaloc::%1:2810").arg(hosts.address(host)); }
};

class TestDeployInstall : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();
    void dryRunChangesNothing();
    void deployInstallsRestoresAndStarts();
    void deploysOverTls();
    void pinnedComponentsAreCreatedByTheirNode();
    void typeNoRepositoryProvidesIsRefusedFirst();
    void unsignedRepositoryIsRefused();
    void failedRestoreUninstalls();
    void restoreDialogInstallsFromRepository();
    void managerViewInstallsAndUninstalls();
    void deploysAcrossHostsFromWebServer();
    void watchHealsWhenANodeDies();
    void keepRunningMovesTheDiagramsComponents();
    void plansDeploysAndHealsAcrossHosts();
    void planViewDeploysThroughTheRestoreDialog();
    void undeployFromTheOnlineMenu();
    void managerAtBootFromTheOnlineMenu();

private:
    RtctlResult rtctl(const QString &command, const QString &system, const QStringList &extra = {}) const;
    QString manager() const { return QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_managerPort); }
    /// The live components of the test's name server, sorted.
    QStringList live() const { return DeployTest::liveInstances(m_live->namingServer()); }
    /// What a failed or undone deploy must not leave: live components and files in the store.
    QStringList leftBehind() const { return live() + filesBelow(m_store); }
    void makeRepository(const QString &dir, bool signedWithKey, const QStringList &debs);
    /// The manager options of a node with its own empty package store @p store.
    QStringList nodeOptions(const QString &store) const;
    /**
     * Starts @p nodes, their stores below the work folder's @p storePrefix-HOST; an empty string
     * when they run, else why not (@p skip set when this machine cannot simulate them).
     */
    QString startSimulatedNodes(SimulatedNodes *nodes, const QString &storePrefix, bool *skip);
    /// A second manager, node B, in the test's name server under nodeb.host_cxt.
    QProcess *startNodeB(QString *nodeB, quint16 port = 0);
    /// doubled.xml with the Doubler pinned to @p nodeB and the rest to manager(); its file.
    QString writePinnedSystem(const QString &nodeB, Profile::RtsProfile *system);

    QTemporaryDir m_work;
    QString m_deb;
    QString m_repo;
    QString m_unsignedRepo;
    QString m_emptyRepo;
    QString m_store;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    quint16 m_managerPort = 0;
    CORBA::ORB_var m_orb;
};

void TestDeployInstall::makeRepository(const QString &dir, bool signedWithKey, const QStringList &debs)
{
    QStringList init {"repo", "init", dir};
    if (signedWithKey)
        init << "--new-key" << "--gnupg-home" << dir + "-gnupg";
    const RtctlResult made = runRtctl(init);
    QVERIFY2(made.code == 0, qPrintable(made.err));
    if (debs.isEmpty())
        return;
    const RtctlResult published = runRtctl(QStringList {"repo", "publish", dir} + debs);
    QVERIFY2(published.code == 0, qPrintable(published.err));
}

void TestDeployInstall::initTestCase()
{
    QVERIFY(m_work.isValid());
    // The main window and the dialogs keep their settings in a folder of the test's own.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_work.filePath("settings"));
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_deployinstall"));
    const QString project = m_work.filePath("Doubler");
    const RtctlResult generated = runRtctl({"gen", doublerProfile, "--lang", "cpp", "-o", project});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QString log;
    QVERIFY2(SdkTest::applyEdit(project, doubling, &log), qPrintable(log));
    QVERIFY2(SdkTest::buildProject(project, RTSTUDIO_BUILD_DIR, &log), qPrintable(log));
    const RtctlResult packaged = runRtctl({"package", project, "-o", m_work.filePath("debs")});
    QVERIFY2(packaged.code == 0, qPrintable(packaged.err));
    m_deb = packaged.lines().value(0);
    m_repo = m_work.filePath("repo");
    makeRepository(m_repo, true, {m_deb});
    m_unsignedRepo = m_work.filePath("unsigned");
    makeRepository(m_unsignedRepo, false, {m_deb});
    m_emptyRepo = m_work.filePath("empty");
    makeRepository(m_emptyRepo, true, {});
    m_store = m_work.filePath("store");
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
}

void TestDeployInstall::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    m_managerPort = LiveTest::freePort();
    const QStringList options = QStringList {"corba.nameservers=" + m_live->namingServer(),
                                             "naming.formats=deployhost.host_cxt/%n.rtc",
                                             "manager.naming_formats=deployhost.host_cxt/%n.mgr"}
        + nodeOptions(m_store);
    QVERIFY2(m_live->startManager(RTMANAGER_PATH, m_managerPort, options, &error),
             qPrintable(error));
}

QStringList TestDeployInstall::nodeOptions(const QString &store) const
{
    return {"manager.modules.load_path=" + m_work.filePath("none"),
            "manager.modules.package_path=" + m_work.filePath("none"),
            "manager.packages.store=" + store,
            "manager.packages.keyring=" + m_repo + "/archive-key.gpg"};
}

void TestDeployInstall::cleanup()
{
    m_live.reset();
    QDir(m_store).removeRecursively();
}

void TestDeployInstall::cleanupTestCase()
{
    for (const QString &repo : {m_repo, m_emptyRepo})
        QProcess::execute("gpgconf", {"--homedir", repo + "-gnupg", "--kill", "all"});
}

RtctlResult TestDeployInstall::rtctl(const QString &command, const QString &system,
                                     const QStringList &extra) const
{
    // Creating through a manager may take a while on a loaded machine.
    return runRtctl(QStringList {command, "--timeout", "20000", "-s", m_live->namingServer(), "-m", manager()}
                    + extra
                    + QStringList {DeployTest::dataFile(system)});
}

void TestDeployInstall::dryRunChangesNothing()
{
    const RtctlResult r = rtctl("deploy", "doubled.xml", {"--repo", m_repo, "--dry-run"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QStringLiteral("install %1 1.0.0 on %2 (Doubler)").arg(package, manager())),
             qPrintable(r.out));
    QVERIFY2(r.out.contains("component Doubler0 create"), qPrintable(r.out));
    QVERIFY2(!r.out.contains("install rtc-aist"), qPrintable(r.out));
    QCOMPARE(leftBehind(), QStringList());
}

void TestDeployInstall::deployInstallsRestoresAndStarts()
{
    const RtctlResult r = rtctl("deploy", "doubled.xml", {"--repo", m_repo});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, manager())),
             qPrintable(r.out));
    QCOMPARE(live(), systemInstances);
    QVERIFY(!filesBelow(m_store).isEmpty());
    // Started: the printer receives the counter's numbers doubled.
    const QString show = QStringLiteral("corbaname::%1#deployhost.host_cxt/Show0.rtc").arg(m_live->namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::integers(LiveTest::componentStatus(m_orb, show, "received_values")).size() >= 3, 20000);
    for (qint64 value : LiveTest::integers(LiveTest::componentStatus(m_orb, show, "received_values")))
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(QString::number(value)));

    const RtctlResult undeployed = rtctl("undeploy", "doubled.xml", {"--uninstall"});
    QVERIFY2(undeployed.code == 0, qPrintable(undeployed.out + undeployed.err));
    QVERIFY2(undeployed.out.contains(QStringLiteral("done uninstall %1 on %2").arg(package, manager())),
             qPrintable(undeployed.out));
    QTRY_COMPARE_WITH_TIMEOUT(leftBehind(), QStringList(), 10000);
}

void TestDeployInstall::deploysOverTls()
{
    // The same life cycle with every connection over TLS: the node's name server, manager and install
    // service serve TLS only, and rtctl presents an operator's certificate of the fleet's authority.
    const QString fleet = m_work.filePath("fleet");
    if (!QFileInfo::exists(fleet + "/ca.pem")) {
        QString made;
        QVERIFY2(runRtctlAll({{"tls", "init", fleet}, {"tls", "issue", fleet, "node", "--host", "127.0.0.1"},
                              {"tls", "issue", fleet, "operator"}},
                             &made),
                 qPrintable(made));
    }
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startTlsNameServer(fleet + "/ca.pem", fleet + "/node.pem", &error), qPrintable(error));
    m_managerPort = LiveTest::freePort();
    const QStringList options = QStringList {"corba.nameservers=" + m_live->namingServer(),
                                             "naming.formats=deployhost.host_cxt/%n.rtc",
                                             "manager.naming_formats=deployhost.host_cxt/%n.mgr",
                                             "corba.ssl.certificate_authority_file=" + fleet + "/ca.pem",
                                             "corba.ssl.key_file=" + fleet + "/node.pem"}
        + nodeOptions(m_store);
    QVERIFY2(m_live->startManager(RTMANAGER_PATH, m_managerPort, options, &error), qPrintable(error));
    const QHash<QString, QString> operatorTls {{"RTSTUDIO_TLS_CA", fleet + "/ca.pem"},
                                               {"RTSTUDIO_TLS_KEY", fleet + "/operator.pem"},
                                               {"XDG_RUNTIME_DIR", m_work.path()}};
    const QStringList target {"--timeout", "20000", "-s", m_live->namingServer(), "-m", manager()};
    const QString system = DeployTest::dataFile("doubled.xml");

    // Without a certificate nothing is installed.
    const RtctlResult anonymous = runRtctl(QStringList {"deploy"} + target + QStringList {"--repo", m_repo, system},
                                           {{"RTSTUDIO_TLS_CA", fleet + "/ca.pem"}, {"XDG_RUNTIME_DIR", m_work.path()}});
    QCOMPARE(anonymous.code, 1);
    QVERIFY2(anonymous.err.contains("certificate"), qPrintable(anonymous.err));
    QVERIFY(filesBelow(m_store).isEmpty());

    const RtctlResult deployed
        = runRtctl(QStringList {"deploy"} + target + QStringList {"--repo", m_repo, system}, operatorTls);
    QVERIFY2(deployed.code == 0, qPrintable(deployed.out + deployed.err));
    QVERIFY2(deployed.out.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, manager())),
             qPrintable(deployed.out));
    QVERIFY(!filesBelow(m_store).isEmpty());
    // Started: the packaged Doubler sends the counter's numbers doubled, over TLS to rtctl's port.
    const QString doubler = QStringLiteral("/%1/deployhost.host_cxt/Doubler0.rtc:out").arg(m_live->namingServer());
    const RtctlResult printed = runRtctl({"print", "-n", "3", doubler}, operatorTls);
    QVERIFY2(printed.code == 0 && printed.lines().size() == 3, qPrintable(printed.out + printed.err));
    for (const QString &line : printed.lines()) {
        const qint64 value = line.section(QStringLiteral("data="), 1).toLongLong();
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(line));
    }

    const RtctlResult undeployed
        = runRtctl(QStringList {"undeploy"} + target + QStringList {"--uninstall", system}, operatorTls);
    QVERIFY2(undeployed.code == 0, qPrintable(undeployed.out + undeployed.err));
    QVERIFY2(undeployed.out.contains(QStringLiteral("done uninstall %1 on %2").arg(package, manager())),
             qPrintable(undeployed.out));
    QTRY_COMPARE_WITH_TIMEOUT(filesBelow(m_store), QStringList(), 10000);
}

// Without -m and without live saved paths, the planner's pins (deploy.pin) name the creating node.
void TestDeployInstall::pinnedComponentsAreCreatedByTheirNode()
{
    Profile::RtsProfile system = DeployTest::loadSystem(DeployTest::dataFile("doubled.xml"));
    Deploy::pinPlacement(&system, {{"Count0", manager()}, {"Doubler0", manager()}, {"Show0", manager()}});
    const QString file = m_work.filePath("pinned.xml");
    Profile::Diagnostics diagnostics;
    QVERIFY(Profile::saveRtsProfileFile(system, file, &diagnostics));
    const RtctlResult unpinned = runRtctl({"deploy", "-s", m_live->namingServer(), "--repo", m_repo, "--dry-run",
                                           DeployTest::dataFile("doubled.xml")});
    QCOMPARE(unpinned.code, 1);
    QVERIFY2(unpinned.out.contains("no manager to create it"), qPrintable(unpinned.out));
    const RtctlResult r = runRtctl({"deploy", "-s", m_live->namingServer(), "--repo", m_repo, "--dry-run", file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.contains(QStringLiteral("install %1 1.0.0 on %2 (Doubler)").arg(package, manager())),
             qPrintable(r.out));
    QVERIFY2(r.out.contains("component Doubler0 create (Doubler?instance_name=Doubler0"), qPrintable(r.out));
    const RtctlResult deployed = runRtctl({"deploy", "--timeout", "20000", "-s", m_live->namingServer(), "--repo", m_repo, file});
    QVERIFY2(deployed.code == 0, qPrintable(deployed.out + deployed.err));
    QVERIFY2(deployed.out.contains(QStringLiteral("done create Doubler0: Doubler?instance_name=Doubler0&exec_cxt.periodic.rate=100 by %1")
                                       .arg(manager())),
             qPrintable(deployed.out));
    QCOMPARE(live(), systemInstances);
}

void TestDeployInstall::typeNoRepositoryProvidesIsRefusedFirst()
{
    const RtctlResult r = rtctl("deploy", "doubled.xml", {"--repo", m_emptyRepo});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("Doubler on %1: not loadable there and no package of %2")
                                .arg(manager(), m_emptyRepo)),
             qPrintable(r.err));
    QCOMPARE(live(), QStringList());
    const RtctlResult without = rtctl("deploy", "doubled.xml");
    QCOMPARE(without.code, 1);
    QVERIFY2(without.err.contains("no repository given"), qPrintable(without.err));
    QCOMPARE(leftBehind(), QStringList());
}

void TestDeployInstall::unsignedRepositoryIsRefused()
{
    const RtctlResult r = rtctl("deploy", "doubled.xml", {"--repo", m_unsignedRepo});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("install %1 1.0.0 on %2").arg(package, manager())),
             qPrintable(r.err));
    QVERIFY2(r.err.contains("unsigned"), qPrintable(r.err));
    QCOMPARE(leftBehind(), QStringList());
}

void TestDeployInstall::failedRestoreUninstalls()
{
    const RtctlResult r = rtctl("deploy", "doubled-broken.xml", {"--repo", m_repo});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("connect doubler-nowhere"), qPrintable(r.err));
    QVERIFY2(r.out.contains(QStringLiteral("rolled back install %1 1.0.0 on %2").arg(package, manager())),
             qPrintable(r.out));
    QTRY_COMPARE_WITH_TIMEOUT(leftBehind(), QStringList(), 10000);
}

// The System Editor's Restore dialog: ticking "Install missing component types" plans the
// install (its column and the dry run name the package and the node), Restore installs and
// creates; with an empty repository the plan names the type and Restore stays disabled.
void TestDeployInstall::restoreDialogInstallsFromRepository()
{
    Deploy::TargetOptions target;
    target.nameServers = {m_live->namingServer()};
    SystemEditor::OnlineSession session;
    SystemEditor::RestoreDialog dialog(&session, DeployTest::loadSystem(DeployTest::dataFile("doubled.xml")),
                                       target);
    QSignalSpy planned(&dialog, &SystemEditor::RestoreDialog::planned);
    dialog.setManagers({manager()});
    dialog.setInstallFrom(m_emptyRepo);
    QVERIFY(planned.wait(20000));
    QVERIFY(dialog.findChild<QCheckBox *>("createCheck")->isChecked());
    auto *restoreButton = dialog.findChild<QPushButton *>("restoreButton");
    QVERIFY(!restoreButton->isEnabled());
    QVERIFY2(dialog.findChild<QLabel *>("summaryLabel")->text().contains("Doubler on " + manager()),
             qPrintable(dialog.findChild<QLabel *>("summaryLabel")->text()));

    dialog.setInstallFrom(m_repo);
    QVERIFY(planned.wait(20000));
    QVERIFY2(restoreButton->isEnabled(), qPrintable(dialog.findChild<QLabel *>("summaryLabel")->text()));
    QTableWidget *components = dialog.componentTable();
    QCOMPARE(components->item(1, SystemEditor::RestoreDialog::NameColumn)->text(), QStringLiteral("Doubler0"));
    QCOMPARE(components->item(1, SystemEditor::RestoreDialog::InstallColumn)->text(), package + " 1.0.0");
    QCOMPARE(components->item(0, SystemEditor::RestoreDialog::InstallColumn)->text(), QString());
    dialog.dryRun();
    QVERIFY(!dialog.progressList()->findItems(QStringLiteral("planned: install %1 1.0.0 on %2 (Doubler)")
                                                  .arg(package, manager()),
                                              Qt::MatchExactly)
                 .isEmpty());
    QCOMPARE(filesBelow(m_store), QStringList());

    QSignalSpy restored(&dialog, &SystemEditor::RestoreDialog::restored);
    QTest::mouseClick(restoreButton, Qt::LeftButton);
    QVERIFY(restored.wait(30000));
    QVERIFY2(restored.at(0).at(0).toBool(), qPrintable(dialog.report().toText()));
    QCOMPARE(live(), systemInstances);
    QVERIFY(!filesBelow(m_store).isEmpty());
    QTRY_VERIFY(!dialog.progressList()->findItems(QStringLiteral("done install %1 1.0.0 on %2").arg(package, manager()),
                                                  Qt::MatchStartsWith)
                     .isEmpty());
    // To look at what the user sees: RTSTUDIO_DEPLOY_SCREENSHOT=file.png.
    if (qEnvironmentVariableIsSet("RTSTUDIO_DEPLOY_SCREENSHOT")) {
        dialog.show();
        QVERIFY(dialog.grab().save(qEnvironmentVariable("RTSTUDIO_DEPLOY_SCREENSHOT")));
    }
}

namespace {

/// The rows of the Manager view's section @p kind ("packages", "loadableModules"), as "name details".
QStringList sectionRows(const SystemEditor::ManagerView &view, const QString &kind)
{
    QStringList rows;
    for (int i = 0; i < view.tree()->topLevelItemCount(); ++i) {
        const QTreeWidgetItem *section = view.tree()->topLevelItem(i);
        if (section->data(0, Qt::UserRole + 1).toString() != kind)
            continue;
        rows << QStringLiteral("(section)");
        for (int j = 0; j < section->childCount(); ++j)
            rows << section->child(j)->text(0) + ' ' + section->child(j)->text(1);
    }
    return rows;
}

} // namespace

// The online Manager view lists what the manager installed, installs by URL and uninstalls: the
// GUI's twin of rtctl node packages / install / uninstall.
void TestDeployInstall::managerViewInstallsAndUninstalls()
{
    SystemEditor::OnlineSession session;
    SystemEditor::ManagerView view(&session);
    QSignalSpy loaded(&view, &SystemEditor::ManagerView::loaded);
    QSignalSpy finished(&view, &SystemEditor::ManagerView::actionFinished);
    view.setManager(manager(), Deploy::ComponentMapper::resolveManager(manager()));
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sectionRows(view, "packages"), QStringList {"(section)"});
    QVERIFY(view.findChild<QPushButton *>("installPackageButton")->isEnabled());

    QDirIterator deb(m_repo + "/pool", {"*.deb"}, QDir::Files, QDirIterator::Subdirectories);
    QVERIFY(deb.hasNext());
    view.installPackage(QUrl::fromLocalFile(deb.next()).toString());
    QVERIFY(finished.wait(30000));
    QCOMPARE(finished.takeFirst().at(0).toString(), QString());
    QTRY_COMPARE_WITH_TIMEOUT(sectionRows(view, "packages"),
                              (QStringList {"(section)", package + " 1.0.0 Doubler"}), 10000);
    QVERIFY(sectionRows(view, "loadableModules").join('\n').contains("Doubler "));

    view.uninstallPackage(package, QString());
    QVERIFY(finished.wait(30000));
    QCOMPARE(finished.takeFirst().at(0).toString(), QString());
    QTRY_COMPARE_WITH_TIMEOUT(sectionRows(view, "packages"), QStringList {"(section)"}, 10000);
    QCOMPARE(filesBelow(m_store), QStringList());

    view.installPackage(QUrl::fromLocalFile(m_unsignedRepo + "/pool/none.deb").toString());
    QVERIFY(finished.wait(30000));
    QVERIFY2(finished.takeFirst().at(0).toString().contains("none.deb"), "a refusal names the package");
}

QString TestDeployInstall::startSimulatedNodes(SimulatedNodes *nodes, const QString &storePrefix, bool *skip)
{
    *skip = true;
    const QString busybox = QStandardPaths::findExecutable(QStringLiteral("busybox"));
    if (busybox.isEmpty())
        return QStringLiteral("no busybox to serve the repository (scripts/install-deps.sh installs it)");
    QString why;
    if (!nodes->hosts.create({"hostA", "hostB", "repohost"}, &why))
        return QStringLiteral("cannot simulate hosts: ") + why;
    *skip = false;
    for (const QString host : {"hostA", "hostB"}) {
        nodes->live[host] = std::make_unique<LiveTest::LiveSystem>(nodes->hosts.liveHost(host));
        if (!nodes->live[host]->startNameServer(&why, 2809))
            return why;
        const QString store = m_work.filePath(storePrefix + host);
        QDir(store).removeRecursively();
        nodes->managers[host] = nodes->live[host]->startManager(
            RTMANAGER_PATH, 2810,
            QStringList {"corba.nameservers=" + nodes->live[host]->namingServer()} + nodeOptions(store), &why);
        if (!nodes->managers[host])
            return why;
    }
    nodes->web = std::make_unique<LiveTest::LiveSystem>(nodes->hosts.liveHost("repohost"));
    const QString webAddress = nodes->hosts.address("repohost");
    const auto serving = [&webAddress] {
        QTcpSocket socket;
        socket.connectToHost(webAddress, 8080);
        return socket.waitForConnected(200);
    };
    if (!nodes->web->startRegistered(busybox, {"httpd", "-f", "-p", webAddress + ":8080", "-h", m_repo}, serving, &why))
        return why;
    nodes->repositoryUrl = QStringLiteral("http://%1:8080/").arg(webAddress);
    return QString();
}

void TestDeployInstall::deploysAcrossHostsFromWebServer()
{
    SimulatedNodes nodes;
    bool skip = false;
    const QString why = startSimulatedNodes(&nodes, "store-", &skip);
    if (skip)
        QSKIP(qPrintable(why));
    QVERIFY2(why.isEmpty(), qPrintable(why));
    auto &live = nodes.live;

    // The system saved with each component where it should run: the Doubler on host B.
    Profile::RtsProfile system = DeployTest::loadSystem(DeployTest::dataFile("doubled.xml"));
    const QHash<QString, QString> placed {{"Count0", "hostA"}, {"Doubler0", "hostB"}, {"Show0", "hostA"}};
    for (Profile::RtsComponent &component : system.components) {
        const QString host = placed.value(component.instanceName);
        component.pathUri = QStringLiteral("%1/%2.host_cxt/%3.rtc")
                                .arg(live.at(host)->namingServer(), host, component.instanceName);
    }
    const QString file = m_work.filePath("spanning.xml");
    Profile::Diagnostics diagnostics;
    QVERIFY(Profile::saveRtsProfileFile(system, file, &diagnostics));

    const QString repoUrl = nodes.repositoryUrl;
    const RtctlResult r = runRtctl({"deploy", "--timeout", "20000", "--repo", repoUrl, file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    const QString hostB = QStringLiteral("/%1/hostB.host_cxt/manager.mgr").arg(live.at("hostB")->namingServer());
    QVERIFY2(r.out.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, hostB)), qPrintable(r.out));
    QVERIFY2(!r.out.contains("on /" + live.at("hostA")->namingServer()), qPrintable(r.out));
    QVERIFY(filesBelow(m_work.filePath("store-hostA")).isEmpty());
    QVERIFY(!filesBelow(m_work.filePath("store-hostB")).isEmpty());
    const QString show = QStringLiteral("corbaname::%1#hostA.host_cxt/Show0.rtc").arg(live.at("hostA")->namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::integers(LiveTest::componentStatus(m_orb, show, "received_values")).size() >= 3, 20000);
    for (qint64 value : LiveTest::integers(LiveTest::componentStatus(m_orb, show, "received_values")))
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(QString::number(value)));

    const RtctlResult undeployed = runRtctl({"undeploy", "--timeout", "20000", "--uninstall", file});
    QVERIFY2(undeployed.code == 0, qPrintable(undeployed.out + undeployed.err));
    for (const QString host : {"hostA", "hostB"}) {
        QTRY_COMPARE_WITH_TIMEOUT(DeployTest::liveInstances(live.at(host)->namingServer()), QStringList(), 10000);
        QCOMPARE(filesBelow(m_work.filePath("store-" + host)), QStringList());
    }
}

// rtctl deploy --watch: the Doubler runs on a second manager; when that manager is killed, the
// watcher plans it anew onto the first (installing it there), and doubled counts flow again.
QProcess *TestDeployInstall::startNodeB(QString *nodeB, quint16 port)
{
    const quint16 portB = port ? port : LiveTest::freePort();
    *nodeB = QStringLiteral("corbaloc::127.0.0.1:%1").arg(portB);
    // Each test's node B starts with nothing installed.
    QDir(m_work.filePath("store-b")).removeRecursively();
    QString error;
    QProcess *managerB = m_live->startManager(
        RTMANAGER_PATH, portB,
        QStringList {"corba.nameservers=" + m_live->namingServer(), "naming.formats=nodeb.host_cxt/%n.rtc",
                     "manager.naming_formats=nodeb.host_cxt/%n.mgr"}
            + nodeOptions(m_work.filePath("store-b")),
        &error);
    if (!managerB)
        qWarning("%s", qPrintable(error));
    return managerB;
}

QString TestDeployInstall::writePinnedSystem(const QString &nodeB, Profile::RtsProfile *system)
{
    *system = DeployTest::loadSystem(DeployTest::dataFile("doubled.xml"));
    Deploy::pinPlacement(system, {{"Count0", manager()}, {"Doubler0", nodeB}, {"Show0", manager()}});
    const QString file = m_work.filePath("watched.xml");
    Profile::Diagnostics diagnostics;
    return Profile::saveRtsProfileFile(*system, file, &diagnostics) ? file : QString();
}

void TestDeployInstall::watchHealsWhenANodeDies()
{
    QString nodeB;
    QProcess *managerB = startNodeB(&nodeB);
    QVERIFY(managerB);
    Profile::RtsProfile system;
    const QString file = writePinnedSystem(nodeB, &system);
    QVERIFY(!file.isEmpty());

    QProcess watcher;
    // Ended however the test ends.
    const auto stopWatcher = qScopeGuard([&watcher] {
        watcher.kill();
        watcher.waitForFinished(5000);
    });
    watcher.setProcessChannelMode(QProcess::MergedChannels);
    watcher.start(RTSTUDIO_BUILD_DIR + QStringLiteral("/cli/rtctl"),
                  {"deploy", "--timeout", "20000", "-s", m_live->namingServer(), "--repo", m_repo, "--watch",
                   "--nodes", manager() + "," + nodeB, "--interval", "100", file});
    QString output;
    const auto read = [&] { return output += QString::fromUtf8(watcher.readAll()); };
    QTRY_VERIFY2_WITH_TIMEOUT(read().contains("watching "), qPrintable(output), 30000);
    QVERIFY2(output.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, nodeB)), qPrintable(output));
    const QString show = QStringLiteral("corbaname::%1#deployhost.host_cxt/Show0.rtc").arg(m_live->namingServer());
    const auto received = [&] {
        return LiveTest::componentStatus(m_orb, show, "received_count").toLong();
    };
    QTRY_VERIFY_WITH_TIMEOUT(received() > 0, 20000);

    QElapsedTimer sinceKill;
    sinceKill.start();
    managerB->kill();
    m_live->stop(managerB);
    const QString lost = QStringLiteral("done node lost %1").arg(nodeB);
    QTRY_VERIFY2_WITH_TIMEOUT(read().contains(lost), qPrintable(output), 20000);
    const auto healed = [&] { return read().mid(output.indexOf(lost)); };
    QTRY_VERIFY2_WITH_TIMEOUT(healed().contains("done activate Doubler0") || healed().contains("failed"),
                              qPrintable(output), 30000);
    QVERIFY2(output.contains(QStringLiteral("done replan Doubler0: Doubler0 -> %1").arg(manager())), qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, manager())), qPrintable(output));
    const long before = received();
    QTRY_VERIFY_WITH_TIMEOUT(received() > before + 2, 20000);
    qInfo("from the kill to doubled counts flowing again: %lld ms", sinceKill.elapsed());
    for (qint64 value : LiveTest::integers(LiveTest::componentStatus(m_orb, show, "received_values")))
        QVERIFY2(value > 0 && value % 2 == 0, qPrintable(QString::number(value)));

    // Node B comes back: a candidate again, but the Doubler stays where it runs.
    QString sameNodeB;
    QVERIFY(startNodeB(&sameNodeB, quint16(QUrl("iiop://" + nodeB.mid(10)).port())));
    QCOMPARE(sameNodeB, nodeB);
    QTRY_VERIFY2_WITH_TIMEOUT(read().contains(QStringLiteral("done node back %1: nothing moved back").arg(nodeB)),
                              qPrintable(output), 20000);
    watcher.terminate();
    QVERIFY(watcher.waitForFinished(20000));
    read();
    QCOMPARE(watcher.exitCode(), 0);
    QVERIFY2(output.contains("stopped watching"), qPrintable(output));

    // rtctl cryo keeps where each component runs now (its saved path), so that a later deploy of
    // the saved file creates the Doubler on the first manager again.
    const QString saved = m_work.filePath("healed.xml");
    const RtctlResult cryo = runRtctl({"cryo", "-o", saved, "/" + m_live->namingServer() + "/deployhost.host_cxt"});
    QVERIFY2(cryo.code == 0, qPrintable(cryo.err));
    const RtctlResult undeployed = runRtctl({"undeploy", "-s", m_live->namingServer(), "--uninstall", saved});
    QVERIFY2(undeployed.code == 0, qPrintable(undeployed.out + undeployed.err));
    QTRY_COMPARE_WITH_TIMEOUT(leftBehind(), QStringList(), 10000);
    const RtctlResult again = runRtctl({"deploy", "--timeout", "20000", "-s", m_live->namingServer(), "--repo", m_repo, saved});
    QVERIFY2(again.code == 0, qPrintable(again.out + again.err));
    QVERIFY2(again.out.contains(QStringLiteral("done install %1 1.0.0 on /%2/deployhost.host_cxt/manager.mgr")
                                    .arg(package, m_live->namingServer())),
             qPrintable(again.out));
}

// Keep Running on an online tab of the saved system: the same heal, and the diagram then shows
// the Doubler where it runs now.
void TestDeployInstall::keepRunningMovesTheDiagramsComponents()
{
    QString nodeB;
    QProcess *managerB = startNodeB(&nodeB);
    QVERIFY(managerB);
    Profile::RtsProfile system;
    const QString file = writePinnedSystem(nodeB, &system);
    const RtctlResult deployed = runRtctl({"deploy", "--timeout", "20000", "-s", m_live->namingServer(), "--repo", m_repo, file});
    QVERIFY2(deployed.code == 0, qPrintable(deployed.out + deployed.err));

    Deploy::TargetOptions target;
    target.nameServers = {m_live->namingServer()};
    SystemEditor::OnlineSession session;
    SystemEditor::OnlineDiagram diagram(&session);
    QAction *keepRunning = diagram.findChild<QAction *>("actionKeepRunning");
    QVERIFY(keepRunning && !keepRunning->isEnabled());
    diagram.setSystem(system, target);
    diagram.setHealRepository(m_repo);
    QVERIFY(keepRunning->isEnabled());
    for (const Deploy::ComponentMapping &c : Deploy::planRestore(system, target).components) {
        QCOMPARE(c.kind, Deploy::MappingKind::Existing);
        diagram.addComponent(c.path, c.ior, QPointF(0, 0));
    }
    QTRY_COMPARE(diagram.livePaths().size(), 3);
    QVERIFY(diagram.livePaths().value("Doubler0").contains("nodeb.host_cxt"));

    QSignalSpy healed(&diagram, &SystemEditor::OnlineDiagram::healed);
    QStringList steps;
    connect(&diagram, &SystemEditor::OnlineDiagram::healStep, this,
            [&steps](const Deploy::DeployStep &step) { steps << step.toString(); });
    keepRunning->setChecked(true);
    QVERIFY(diagram.isHealing());
    managerB->kill();
    m_live->stop(managerB);
    QVERIFY2(healed.wait(30000), qPrintable(steps.join('\n')));
    const auto moved = healed.at(0).at(0).value<QHash<QString, QString>>();
    QCOMPARE(moved.keys(), QStringList {"Doubler0"});
    QCOMPARE(moved.value("Doubler0"), manager());
    QVERIFY2(diagram.livePaths().value("Doubler0").contains("deployhost.host_cxt"),
             qPrintable(diagram.livePaths().value("Doubler0")));
    QTRY_COMPARE_WITH_TIMEOUT(diagram.state("Doubler0"), Corba::LifeCycleState::Active, 10000);
    QVERIFY(diagram.unreachableComponents().isEmpty());
    QVERIFY2(steps.contains(QStringLiteral("done node lost %1: it ran Doubler0").arg(nodeB)), qPrintable(steps.join('\n')));
    QVERIFY2(diagram.findChild<QLabel *>("statusLabel")->text().contains("Doubler0 to " + manager()),
             qPrintable(diagram.findChild<QLabel *>("statusLabel")->text()));
    keepRunning->setChecked(false);
    QVERIFY(!diagram.isHealing());
}

// Across hosts in network namespaces, with the repository on a web server: rtctl deploy --plan
// places the free Doubler between a counter pinned to host A and a printer pinned to host B,
// --watch heals when the manager of the Doubler's host is killed, and doubled counts arrive
// again on the host that is left.
void TestDeployInstall::plansDeploysAndHealsAcrossHosts()
{
    SimulatedNodes nodes;
    bool skip = false;
    const QString why = startSimulatedNodes(&nodes, "heal-", &skip);
    if (skip)
        QSKIP(qPrintable(why));
    QVERIFY2(why.isEmpty(), qPrintable(why));
    auto &live = nodes.live;
    auto &managers = nodes.managers;
    QHash<QString, QString> node;
    for (const QString host : {"hostA", "hostB"})
        node[host] = nodes.node(host);
    Profile::RtsProfile system = DeployTest::loadSystem(DeployTest::dataFile("doubled.xml"));
    Deploy::pinPlacement(&system, {{"Count0", node.value("hostA")}, {"Show0", node.value("hostB")}});
    const QString file = m_work.filePath("planned.xml");
    Profile::Diagnostics diagnostics;
    QVERIFY(Profile::saveRtsProfileFile(system, file, &diagnostics));

    QProcess watcher;
    const auto stopWatcher = qScopeGuard([&watcher] {
        watcher.kill();
        watcher.waitForFinished(5000);
    });
    watcher.setProcessChannelMode(QProcess::MergedChannels);
    watcher.start(RTSTUDIO_BUILD_DIR + QStringLiteral("/cli/rtctl"),
                  {"deploy", "--timeout", "20000", "-s", live.at("hostA")->namingServer(), "-s",
                   live.at("hostB")->namingServer(), "--repo", nodes.repositoryUrl,
                   "--plan", "--nodes", node.value("hostA") + "," + node.value("hostB"), "--watch", "--interval",
                   "100", file});
    QString output;
    const auto read = [&] { return output += QString::fromUtf8(watcher.readAll()); };
    QTRY_VERIFY2_WITH_TIMEOUT(read().contains("watching "), qPrintable(output), 30000);
    static const QRegularExpression planned(QStringLiteral("^plan Doubler0 -> (\\S+)$"), QRegularExpression::MultilineOption);
    const QString doublerNode = planned.match(output).captured(1);
    QVERIFY2(node.values().contains(doublerNode), qPrintable(output));
    const QString lostHost = node.key(doublerNode);
    const QString leftHost = lostHost == "hostA" ? "hostB" : "hostA";
    QVERIFY2(output.contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, doublerNode)), qPrintable(output));
    // Data flows from host A to host B.
    const auto received = [&](const QString &host) {
        return LiveTest::componentStatus(
                   m_orb, QStringLiteral("corbaname::%1#%2.host_cxt/Show0.rtc").arg(live.at(host)->namingServer(), host),
                   "received_count")
            .toLong();
    };
    QTRY_VERIFY_WITH_TIMEOUT(received("hostB") > 0, 20000);

    QElapsedTimer sinceKill;
    sinceKill.start();
    managers.at(lostHost)->kill();
    live.at(lostHost)->stop(managers.at(lostHost));
    const QString lost = QStringLiteral("done node lost %1").arg(doublerNode);
    QTRY_VERIFY2_WITH_TIMEOUT(read().contains(lost), qPrintable(output), 20000);
    const auto healed = [&] { return read().mid(output.indexOf(lost)); };
    QTRY_VERIFY2_WITH_TIMEOUT(healed().contains("done activate Doubler0") || healed().contains("failed"),
                              qPrintable(output), 30000);
    QVERIFY2(healed().contains(QStringLiteral("Doubler0 -> %1").arg(node.value(leftHost))), qPrintable(healed()));
    QVERIFY2(healed().contains(QStringLiteral("done install %1 1.0.0 on %2").arg(package, node.value(leftHost))),
             qPrintable(healed()));
    const long before = received(leftHost);
    QTRY_VERIFY_WITH_TIMEOUT(received(leftHost) > before + 2, 20000);
    qInfo("across hosts, from the kill to doubled counts flowing again: %lld ms", sinceKill.elapsed());
    watcher.terminate();
    QVERIFY(watcher.waitForFinished(20000));
    QCOMPARE(watcher.exitCode(), 0);
}

// The System Editor's Plan view on two live managers: the Doubler pinned (dragged) to node B, the
// rest planned; Deploy hands the pinned system and the plan's repository to the Restore dialog,
// which installs the Doubler on node B and creates every component on its node.
void TestDeployInstall::planViewDeploysThroughTheRestoreDialog()
{
    QString nodeB;
    QVERIFY(startNodeB(&nodeB));
    Profile::RtsProfile system;
    QVERIFY(!writePinnedSystem(nodeB, &system).isEmpty());
    // Only the Doubler stays pinned; the planner places the others.
    for (Profile::RtsComponent &component : system.components) {
        if (component.instanceName != "Doubler0")
            component.properties.clear();
    }
    Deploy::TargetOptions target;
    target.nameServers = {m_live->namingServer()};
    SystemEditor::OnlineSession session;
    std::unique_ptr<SystemEditor::RestoreDialog> opened;
    Studio::RtsEditor::setDeployHandler([&](const Profile::RtsProfile &pinned, const QString &repository) {
        opened = std::make_unique<SystemEditor::RestoreDialog>(&session, pinned, target);
        opened->setCreateMissing(true, QString());
        opened->setInstallFrom(repository);
    });
    const auto resetHandler = qScopeGuard([] { Studio::RtsEditor::setDeployHandler({}); });
    Studio::RtsDocument document(system);
    Studio::RtsEditor editor(&document);
    SystemEditor::PlanView *plan = editor.planView();
    QSignalSpy planned(plan, &SystemEditor::PlanView::planChanged);
    plan->openRepository(m_repo);
    QTRY_VERIFY_WITH_TIMEOUT(!plan->isBusy(), 20000);
    plan->readFactsFromManagers({manager(), nodeB});
    QTRY_VERIFY_WITH_TIMEOUT(!plan->isBusy() && plan->facts().size() == 2, 20000);
    plan->replan();
    QTRY_VERIFY2_WITH_TIMEOUT(!plan->isBusy() && plan->plan().feasible, qPrintable(plan->statusText()), 20000);
    QCOMPARE(plan->plan().placement("Doubler0")->node, nodeB);
    QVERIFY(plan->deployAction()->isEnabled());
    plan->deployAction()->trigger();
    QVERIFY(opened);
    QSignalSpy dialogPlanned(opened.get(), &SystemEditor::RestoreDialog::planned);
    QTRY_VERIFY_WITH_TIMEOUT(opened->currentDeployPlan().installs.size() == 1
                                 && opened->findChild<QPushButton *>("restoreButton")->isEnabled(),
                             20000);
    QCOMPARE(opened->currentDeployPlan().installs.first().node, nodeB);
    QSignalSpy restored(opened.get(), &SystemEditor::RestoreDialog::restored);
    opened->restore();
    QVERIFY(restored.wait(30000));
    QVERIFY2(restored.at(0).at(0).toBool(), qPrintable(opened->report().toText()));
    // Each component where the plan put it: the Doubler under node B's naming context.
    QStringList doublers;
    for (const auto &entry : Deploy::ComponentMapper::liveComponents({"/" + m_live->namingServer()}, nullptr))
        doublers << entry.path;
    QVERIFY2(doublers.join(' ').contains("nodeb.host_cxt/Doubler0.rtc"), qPrintable(doublers.join(' ')));
}

// Online → Undeploy System and Uninstall Its Packages: the GUI's rtctl undeploy --uninstall.
void TestDeployInstall::undeployFromTheOnlineMenu()
{
    const RtctlResult deployed = rtctl("deploy", "doubled.xml", {"--repo", m_repo});
    QVERIFY2(deployed.code == 0, qPrintable(deployed.out + deployed.err));
    QCOMPARE(live(), systemInstances);
    Studio::MainWindow window;
    QVERIFY(window.onlineDocks()->nameService()->addServer(m_live->namingServer()));
    QVERIFY(window.findChild<QAction *>("actionUndeployUninstall"));
    // The manager that created the components, as the deploy's -m named it.
    Profile::RtsProfile system = DeployTest::loadSystem(DeployTest::dataFile("doubled.xml"));
    Deploy::pinPlacement(&system, {{"Count0", manager()}, {"Doubler0", manager()}, {"Show0", manager()}});
    std::optional<Deploy::DeployReport> report;
    window.onlineDocks()->undeploy(system, true, [&report](const Deploy::DeployReport &r) { report = r; });
    QTRY_VERIFY_WITH_TIMEOUT(report.has_value(), 30000);
    QVERIFY2(report->ok, qPrintable(report->toText()));
    QTRY_COMPARE_WITH_TIMEOUT(leftBehind(), QStringList(), 10000);
}

// Online → Start a Manager at Boot: the unit rtctl node enable writes (here into a folder of the
// test's own, without systemctl), accepted by systemd-analyze when it is installed; Do Not Start
// removes it.
void TestDeployInstall::managerAtBootFromTheOnlineMenu()
{
    const QString units = m_work.filePath("units");
    QVERIFY(QDir().mkpath(units));
    QSettings().setValue("node/unitDirectory", units);
    const auto resetSetting = qScopeGuard([] { QSettings().remove("node/unitDirectory"); });
    const QString config = m_work.filePath("boot.conf");
    QFile conf(config);
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("manager.packages.store: " + m_store.toUtf8() + "\n");
    conf.close();
    Studio::MainWindow window;
    QVERIFY(window.findChild<QAction *>("actionManagerAtBoot"));
    std::optional<SystemEditor::OnlineResult> enabled;
    window.onlineDocks()->setManagerAtBoot(true, config, [&enabled](const auto &result) { enabled = result; });
    QTRY_VERIFY_WITH_TIMEOUT(enabled, 30000);
    QVERIFY2(enabled->ok, qPrintable(enabled->error));
    const std::optional<QString> path = enabled->value.toString();
    QCOMPARE(*path, units + "/rtmanager.service");
    QFile unit(*path);
    QVERIFY(unit.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(unit.readAll());
    QVERIFY2(text.contains(QRegularExpression("\nExecStart=/\\S*rtmanager -f " + QRegularExpression::escape(config) + "\n")),
             qPrintable(text));
    const QString analyze = QStandardPaths::findExecutable("systemd-analyze");
    if (!analyze.isEmpty()) {
        QProcess verify;
        verify.setProcessChannelMode(QProcess::MergedChannels);
        verify.start(analyze, {"verify", *path});
        QVERIFY(verify.waitForFinished(60000));
        QVERIFY2(verify.exitCode() == 0, qPrintable(QString::fromUtf8(verify.readAll())));
    }
    std::optional<SystemEditor::OnlineResult> disabled;
    window.onlineDocks()->setManagerAtBoot(false, QString(), [&disabled](const auto &result) { disabled = result; });
    QTRY_VERIFY_WITH_TIMEOUT(disabled, 30000);
    QVERIFY2(disabled->ok, qPrintable(disabled->error));
    QVERIFY(!QFile::exists(*path));
}

QTEST_MAIN(TestDeployInstall)
#include "tst_deployinstall.moc"
