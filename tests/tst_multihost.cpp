// SPDX-License-Identifier: MIT
// Deployment across hosts. Two hosts are simulated with network namespaces (root only; skipped
// elsewhere), each with its own omniNames on 2809 and master rtmanager on 2810 with rtc.conf's
// defaults, as on two machines. rtctl, run from the test's own namespace as from a third
// machine, restores one system spanning both, starts it, saves it back and compares it with the
// file; a manager killed in the middle of a restore leaves nothing behind on either host.
#include "livesystem.h"
#include "profileio.h"
#include "rtctlrunner.h"
#include "rtsprofile.h"
#include "simulatedhosts.h"

#include <RTC.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <arpa/inet.h>
#include <csignal>

#include <algorithm>
#include <map>
#include <memory>

namespace {

const QString hostA = QStringLiteral("hostA");
const QString hostB = QStringLiteral("hostB");
// Each host has its own ports: OpenRTM's usual ones.
constexpr quint16 namingPort = 2809;
constexpr quint16 managerPort = 2810;
// The bundled example: ConsoleIn0 (saved on host A) feeds ConsoleOut0 (saved on host B).
const QString source = QStringLiteral("ConsoleIn0");
const QString sink = QStringLiteral("ConsoleOut0");
const QString connectorId = QStringLiteral("6aa42771-908e-5b82-99ff-f41ebf13c242");

// How /proc/net/tcp writes an IPv4 endpoint: the address as the 32-bit value of its bytes in
// network order, and the port, both in upper-case hex.
QByteArray procNetEndpoint(const QString &address, quint16 port)
{
    in_addr raw {};
    ::inet_pton(AF_INET, address.toLatin1().constData(), &raw);
    return QByteArray::number(raw.s_addr, 16).toUpper().rightJustified(8, '0') + ':'
        + QByteArray::number(port, 16).toUpper().rightJustified(4, '0');
}

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

} // namespace

class TestMultiHost : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();

    void restoresStartsAndSavesAcrossHosts();
    void masterCreatesOnTheOtherHostByAddress();
    void killedManagerRollsBackBothHosts_data();
    void killedManagerRollsBackBothHosts();

private:
    QString server(const QString &host) const;
    /// `/ADDRESS:2809/HOST.host_cxt`: where rtmanager's default naming.formats put its objects.
    QString context(const QString &host) const;
    QString managerLocation(const QString &host) const;
    QString otherHost(const QString &host) const { return host == hostA ? hostB : hostA; }
    QString componentOn(const QString &host) const { return host == hostA ? source : sink; }
    /// The live path of the component saved on `host`.
    QString componentPath(const QString &host) const;
    bool startManager(const QString &host, QString *error);
    QString writeSystem(bool sinkFirst, QString *error) const;
    RtctlResult rtctl(const QStringList &arguments) const;
    QStringList componentsOf(const QString &host) const;
    QStringList namesOn(const QString &host) const;
    long sinkReceived() const;
    void checkSaved(const QString &file) const;
    bool tcpConnected(const QString &from, const QString &to, quint16 port) const;
    RtctlResult restoreKilling(const QString &killed, const QString &killAfter,
                               const QStringList &arguments);

    LiveTest::SimulatedHosts m_hosts;
    std::map<QString, std::unique_ptr<LiveTest::LiveSystem>> m_live;
    std::map<QString, QProcess *> m_managers;
    CORBA::ORB_var m_orb;
    QTemporaryDir m_dir;
};

void TestMultiHost::initTestCase()
{
    QString why;
    if (!m_hosts.create({hostA, hostB}, &why))
        QSKIP(qPrintable(QStringLiteral("cannot simulate hosts: ") + why));
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    omniORB::setClientCallTimeout(3000);
    omniORB::setClientConnectTimeout(3000);
}

// Every test starts from hosts with empty name servers and fresh managers.
void TestMultiHost::init()
{
    for (const QString &host : {hostA, hostB}) {
        m_live[host] = std::make_unique<LiveTest::LiveSystem>(m_hosts.liveHost(host));
        QString error;
        QVERIFY2(m_live[host]->startNameServer(&error, namingPort), qPrintable(error));
        QVERIFY2(startManager(host, &error), qPrintable(error));
    }
}

void TestMultiHost::cleanup()
{
    m_managers.clear();
    m_live.clear();
}

void TestMultiHost::cleanupTestCase()
{
    cleanup();
    m_hosts.remove();
    if (!CORBA::is_nil(m_orb))
        m_orb->destroy();
}

QString TestMultiHost::server(const QString &host) const
{
    return QStringLiteral("%1:%2").arg(m_hosts.address(host)).arg(namingPort);
}

QString TestMultiHost::context(const QString &host) const
{
    return QStringLiteral("/%1/%2.host_cxt").arg(server(host), host);
}

QString TestMultiHost::componentPath(const QString &host) const
{
    return context(host) + '/' + componentOn(host) + ".rtc";
}

QString TestMultiHost::managerLocation(const QString &host) const
{
    return QStringLiteral("corbaloc::%1:%2").arg(m_hosts.address(host)).arg(managerPort);
}

// rtc.conf's defaults otherwise: the manager and its components are named after the host
// (%h.host_cxt), and it listens on a Unix socket too, which peers on other hosts must ignore.
bool TestMultiHost::startManager(const QString &host, QString *error)
{
    QProcess *manager = m_live.at(host)->startManager(RTMANAGER_PATH, managerPort,
                                                      {"corba.nameservers=" + server(host)}, error);
    m_managers[host] = manager;
    return manager != nullptr;
}

// The bundled ConsoleInOut system with each component saved where rtshell's rtcryo puts it:
// ConsoleIn0 on host A, ConsoleOut0 on host B.
QString TestMultiHost::writeSystem(bool sinkFirst, QString *error) const
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(
        RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml"),
        &diagnostics);
    if (!loaded || !loaded->rts) {
        *error = QStringLiteral("cannot read the ConsoleInOut example");
        return QString();
    }
    Profile::RtsProfile system = *loaded->rts;
    for (const QString &host : {hostA, hostB})
        system.component(componentOn(host))->pathUri = componentPath(host).mid(1);
    if (sinkFirst)
        std::reverse(system.components.begin(), system.components.end());
    const QString file = m_dir.filePath(QStringLiteral("spanning.xml"));
    if (!Profile::saveRtsProfileFile(system, file, &diagnostics)) {
        *error = QStringLiteral("cannot write %1").arg(file);
        return QString();
    }
    return file;
}

RtctlResult TestMultiHost::rtctl(const QStringList &arguments) const
{
    return runRtctl(arguments, {{"RTCTREE_NAMESERVERS", server(hostA) + ';' + server(hostB)}});
}

/// Instance names of the components of `host`'s manager, sorted.
QStringList TestMultiHost::componentsOf(const QString &host) const
{
    const RtctlResult listed = rtctl({"mgr", managerLocation(host), "list", "--json"});
    QStringList names;
    for (const QJsonValue &component : listed.json()[QStringLiteral("components")].toArray())
        names.append(component[QStringLiteral("instanceName")].toString());
    if (listed.code != 0)
        names.append(QStringLiteral("(%1)").arg(listed.err.trimmed()));
    return sorted(names);
}

/// The names bound in `host`'s name server under its host context, sorted.
QStringList TestMultiHost::namesOn(const QString &host) const
{
    const RtctlResult listed = rtctl({"ls", "--json", context(host)});
    QStringList names;
    for (const QJsonValue &entry : listed.json().array())
        names.append(entry[QStringLiteral("name")].toString());
    if (listed.code != 0)
        names.append(QStringLiteral("(%1)").arg(listed.err.trimmed()));
    return sorted(names);
}

/// How many samples ConsoleOut0 on host B has received (its SDO status); -1 when unknown.
long TestMultiHost::sinkReceived() const
{
    const QString name
        = QStringLiteral("corbaname::%1#%2.host_cxt/%3.rtc").arg(server(hostB), hostB, sink);
    try {
        CORBA::Object_var object = m_orb->string_to_object(name.toUtf8().constData());
        RTC::RTObject_var component = RTC::RTObject::_narrow(object);
        SDOPackage::NVList_var status = component->get_status_list();
        bool ok = false;
        const long count = nv(status.in(), "received_count").toLong(&ok);
        return ok ? count : -1;
    } catch (const CORBA::Exception &) {
        return -1;
    }
}

// Whether a process on `from` has an established TCP connection to `to`:`port`. A process's
// /proc/PID/net/tcp lists the connections of its network namespace, here: of its host.
bool TestMultiHost::tcpConnected(const QString &from, const QString &to, quint16 port) const
{
    QFile table(QStringLiteral("/proc/%1/net/tcp").arg(m_managers.at(from)->processId()));
    if (!table.open(QIODevice::ReadOnly))
        return false;
    const QByteArray remote = procNetEndpoint(m_hosts.address(to), port);
    const QByteArray established = "01";
    for (const QByteArray &line : table.readAll().split('\n')) {
        const QList<QByteArray> fields = line.simplified().split(' ');
        if (fields.size() > 3 && fields.at(2) == remote && fields.at(3) == established)
            return true;
    }
    return false;
}

// The system cryo saved in `file`: each component at its live path, and the connector.
void TestMultiHost::checkSaved(const QString &file) const
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(file, &diagnostics);
    QVERIFY(loaded && loaded->rts);
    const Profile::RtsProfile saved = *loaded->rts;
    QCOMPARE(int(saved.components.size()), 2);
    for (const QString &host : {hostA, hostB}) {
        const Profile::RtsComponent *component = saved.component(componentOn(host));
        QVERIFY2(component, qPrintable(componentOn(host)));
        QCOMPARE('/' + component->pathUri, componentPath(host));
    }
    QCOMPARE(int(saved.dataPortConnectors.size()), 1);
    const Profile::RtsDataPortConnector &connector = saved.dataPortConnectors.first();
    QCOMPARE(connector.connectorId, connectorId);
    QCOMPARE(connector.source.instanceName + '/' + connector.source.portName,
             QStringLiteral("ConsoleIn0/ConsoleIn0.out"));
    QCOMPARE(connector.target.instanceName + '/' + connector.target.portName,
             QStringLiteral("ConsoleOut0/ConsoleOut0.in"));
}

void TestMultiHost::restoresStartsAndSavesAcrossHosts()
{
    QString error;
    const QString system = writeSystem(false, &error);
    QVERIFY2(!system.isEmpty(), qPrintable(error));

    // Without -m each component is created by the manager registered beside its saved path.
    const RtctlResult restored = rtctl({"resurrect", "--create", system});
    QVERIFY2(restored.code == 0, qPrintable(restored.out + restored.err));
    for (const QString &host : {hostA, hostB}) {
        const QString instance = componentOn(host);
        const QString line
            = QStringLiteral(
                  "done create %1: %2?instance_name=%1&exec_cxt.periodic.rate=1000 by %3")
                  .arg(instance, instance.chopped(1), context(host) + "/manager.mgr");
        QVERIFY2(restored.lines().contains(line), qPrintable(restored.out));
        QCOMPARE(componentsOf(host), QStringList {instance});
        QCOMPARE(namesOn(host), sorted({instance + ".rtc", "manager.mgr"}));
    }
    QVERIFY2(restored.lines().contains("done connect " + connectorId
                                       + ": ConsoleIn0.out -> ConsoleOut0.in"),
             qPrintable(restored.out));

    const RtctlResult started = rtctl({"start", system});
    QVERIFY2(started.code == 0, qPrintable(started.out + started.err));
    QCOMPARE(started.lines(),
             QStringList({"done activate ConsoleOut0.0", "done activate ConsoleIn0.0"}));
    // The samples go from host A's process to host B's over TCP, across the link between them.
    QTRY_VERIFY_WITH_TIMEOUT(sinkReceived() > 50, 10000);
    QVERIFY(tcpConnected(hostA, hostB, managerPort));

    // Saved back from both hosts: the same components at the same paths, and the connector.
    const QString frozen = m_dir.filePath(QStringLiteral("frozen.xml"));
    const RtctlResult cryo
        = rtctl({"cryo", "-n", "Frozen", "-o", frozen, context(hostA), context(hostB)});
    QVERIFY2(cryo.code == 0, qPrintable(cryo.err));
    checkSaved(frozen);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(rtctl({"diff", system}).code, 0);
    QCOMPARE(rtctl({"diff", frozen}).code, 0);

    const RtctlResult stopped = rtctl({"stop", system});
    QCOMPARE(stopped.lines(),
             QStringList({"done deactivate ConsoleIn0.0", "done deactivate ConsoleOut0.0"}));
    QCOMPARE(rtctl({"teardown", system}).lines(), QStringList({"done disconnect " + connectorId}));
    const RtctlResult drift = rtctl({"diff", system});
    QCOMPARE(drift.code, 1);
    QCOMPARE(drift.lines(),
             QStringList({"missing connector " + connectorId
                          + ": saved 'ConsoleIn0.out -> ConsoleOut0.in'"}));

    // The saved system restores onto the hosts it names, from nothing.
    QCOMPARE(rtctl({"exit", componentPath(hostA), componentPath(hostB)}).code, 0);
    QTRY_COMPARE(componentsOf(hostA), QStringList());
    QTRY_COMPARE(componentsOf(hostB), QStringList());
    const RtctlResult again = rtctl({"resurrect", "--create", frozen});
    QVERIFY2(again.code == 0, qPrintable(again.out + again.err));
    QCOMPARE(componentsOf(hostA), QStringList {source});
    QCOMPARE(componentsOf(hostB), QStringList {sink});
    QCOMPARE(rtctl({"diff", frozen}).code, 0);
}

// rtshell's way for hosts without their own name server entry: -m names one master, and
// --host-manager gives each saved host's manager_address, to which the master forwards.
void TestMultiHost::masterCreatesOnTheOtherHostByAddress()
{
    QString error;
    const QString system = writeSystem(false, &error);
    QVERIFY2(!system.isEmpty(), qPrintable(error));
    const QString hostBManager
        = QStringLiteral("%1:%2").arg(m_hosts.address(hostB)).arg(managerPort);
    const QStringList throughMaster {"resurrect",
                                     "--create",
                                     "-m",
                                     managerLocation(hostA),
                                     "--host-manager",
                                     hostB + '=' + hostBManager,
                                     system};

    const RtctlResult restored = rtctl(throughMaster);
    QVERIFY2(restored.code == 0, qPrintable(restored.out + restored.err));
    QVERIFY2(
        restored.lines().contains("done create ConsoleOut0: ConsoleOut?instance_name=ConsoleOut0"
                                  "&exec_cxt.periodic.rate=1000&manager_address="
                                  + hostBManager + " by " + managerLocation(hostA)),
        qPrintable(restored.out));
    QCOMPARE(componentsOf(hostA), QStringList {source});
    QCOMPARE(componentsOf(hostB), QStringList {sink});
    QCOMPARE(rtctl({"diff", system}).code, 0);

    // Host B's manager restarts, losing its component; host A's master still has a connection to
    // the old process, and must reach the new one.
    m_live.at(hostB)->stop(m_managers.at(hostB));
    QVERIFY2(startManager(hostB, &error), qPrintable(error));
    const RtctlResult drift = rtctl({"diff", system});
    QCOMPARE(drift.code, 1);
    QCOMPARE(drift.lines().size(), 1);
    QVERIFY2(drift.out.startsWith("missing component ConsoleOut0: "), qPrintable(drift.out));
    const RtctlResult again = rtctl(throughMaster);
    QVERIFY2(again.code == 0, qPrintable(again.out + again.err));
    // ConsoleIn0 kept its end of the connector to the dead process; it is made anew.
    QVERIFY2(again.lines().contains("done connect " + connectorId
                                    + ": ConsoleIn0.out -> "
                                      "ConsoleOut0.in (replaced a broken connector)"),
             qPrintable(again.out));
    QCOMPARE(componentsOf(hostB), QStringList {sink});
    QCOMPARE(rtctl({"diff", system}).code, 0);
}

// Runs rtctl with `arguments` while the manager of `killed` is stopped, so that it takes requests
// without answering, and kills that manager once rtctl has printed the line `killAfter`.
RtctlResult TestMultiHost::restoreKilling(const QString &killed, const QString &killAfter,
                                          const QStringList &arguments)
{
    RtctlResult result;
    const qint64 pid = m_managers.at(killed)->processId();
    if (::kill(pid_t(pid), SIGSTOP) != 0 || !LiveTest::waitUntilStopped(pid))
        return result;
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("RTCTREE_NAMESERVERS", server(hostA) + ';' + server(hostB));
    process.setProcessEnvironment(environment);
    process.start(RTCTL_PATH, arguments);
    QByteArray out;
    const QDeadlineTimer deadline(30000);
    while (!out.contains(killAfter.toUtf8()) && !deadline.hasExpired()
           && process.state() != QProcess::NotRunning) {
        if (process.waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime()))))
            out += process.readAllStandardOutput();
    }
    m_live.at(killed)->stop(m_managers.at(killed));
    if (!process.waitForFinished(30000))
        return result;
    result.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    result.out = QString::fromUtf8(out + process.readAllStandardOutput());
    result.err = QString::fromUtf8(process.readAllStandardError());
    return result;
}

void TestMultiHost::killedManagerRollsBackBothHosts_data()
{
    QTest::addColumn<QString>("killed");
    QTest::addColumn<bool>("throughMaster");
    QTest::newRow("host B's manager") << hostB << false;
    QTest::newRow("host A's manager") << hostA << false;
    QTest::newRow("host B's manager, behind host A's master") << hostB << true;
}

// The survivor's component is created first; then the restore waits on the stopped manager of
// the other host, which is killed: the restore fails naming it, and undoes what it made.
void TestMultiHost::killedManagerRollsBackBothHosts()
{
    QFETCH(QString, killed);
    QFETCH(bool, throughMaster);
    const QString survivor = otherHost(killed);
    QString error;
    const QString system = writeSystem(killed == hostA, &error);
    QVERIFY2(!system.isEmpty(), qPrintable(error));
    const QString killedAddress
        = QStringLiteral("%1:%2").arg(m_hosts.address(killed)).arg(managerPort);
    QStringList arguments {"resurrect", "--create"};
    if (throughMaster)
        arguments << "-m" << managerLocation(survivor) << "--host-manager"
                  << killed + '=' + killedAddress;
    arguments << system;

    const RtctlResult result
        = restoreKilling(killed, "done create " + componentOn(survivor), arguments);
    QCOMPARE(result.code, 1);
    const QString &err = result.err;
    QVERIFY2(err.startsWith("rtctl resurrect: create " + componentOn(killed) + ": "),
             qPrintable(err));
    if (throughMaster) {
        QVERIFY2(err.contains("manager at " + killedAddress + " unreachable"), qPrintable(err));
    } else {
        QVERIFY2(err.contains(context(killed) + "/manager.mgr: "), qPrintable(err));
        QVERIFY2(err.contains("(its process at " + killedAddress + ')'), qPrintable(err));
    }
    const QString rolledBack = "rolled back create " + componentOn(survivor) + ": undone";
    QCOMPARE(result.lines().count(rolledBack), 1);
    // Nothing made by the restore is left: the survivor's component is gone again, and the
    // killed host's name server has only its (dead) manager's entry.
    QTRY_COMPARE(componentsOf(survivor), QStringList());
    QTRY_COMPARE(namesOn(survivor), QStringList {"manager.mgr"});
    QCOMPARE(namesOn(killed), QStringList {"manager.mgr"});
}

QTEST_GUILESS_MAIN(TestMultiHost)
#include "tst_multihost.moc"
