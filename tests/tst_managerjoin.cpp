// SPDX-License-Identifier: MIT
// Slaves joining an rtmanager master, live: several at once while the master is busy answering
// aggregated queries, and slaves the master spawns, which must know they joined before
// create_component returns (a master going down right after used to leave them reporting
// "cannot join master").
#include "corbautil.h"
#include "livesystem.h"

#include <Manager.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"

#include <QtTest>

#include <atomic>
#include <csignal>
#include <thread>

namespace {

constexpr int SlaveCount = 5;

// A process that has exited, also when nobody has reaped it yet (slaves orphaned by their master).
bool gone(pid_t pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (::kill(pid, 0) != 0 || !stat.open(QIODevice::ReadOnly))
        return true;
    const QByteArray text = stat.readAll();
    return text.mid(text.lastIndexOf(')') + 2, 1) == "Z";
}

/// The parent process of @p pid (0 when it is gone).
pid_t parentOf(pid_t pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray text = stat.readAll();
    // "pid (comm) state ppid …": the name may hold spaces, the fields after it do not.
    return pid_t(text.mid(text.lastIndexOf(')') + 2).split(' ').value(1).toInt());
}

/// The command line of @p pid as ps shows it (arguments joined by spaces).
QByteArray commandLine(pid_t pid)
{
    QFile file(QStringLiteral("/proc/%1/cmdline").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll().replace('\0', ' ').trimmed();
}

/// Asks @p manager for its (aggregated) components over and over until stopped.
class Hammer
{
public:
    explicit Hammer(RTM::Manager_ptr manager)
        : m_manager(RTM::Manager::_duplicate(manager))
        , m_thread([this] { run(); })
    { }
    ~Hammer()
    {
        m_stop = true;
        m_thread.join();
    }
    int calls() const { return m_calls; }

private:
    void run()
    {
        while (!m_stop) {
            try {
                RTC::ComponentProfileList_var profiles = m_manager->get_component_profiles();
                ++m_calls;
            } catch (const CORBA::Exception &) {
                // The master going down at the end of a test is no concern here.
            }
        }
    }

    RTM::Manager_var m_manager;
    std::atomic_bool m_stop {false};
    std::atomic_int m_calls {0};
    std::thread m_thread;
};

} // namespace

class TestManagerJoin : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();

    void slavesStartedAtOnceAllJoin();
    void spawnedSlavesHaveJoinedWhenCreateReturns();
    void slavesStartThroughForkServer();

private:
    QStringList slaveNames();
    /// A master in @p process (not the fixture's), naming off, once it answers; nil when it does not.
    RTM::Manager_ptr startOwnMaster(QProcess &process);

    CORBA::ORB_var m_orb;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    std::unique_ptr<QTemporaryDir> m_dir;
    RTM::Manager_var m_master;
    quint16 m_port = 0;
};

void TestManagerJoin::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    omniORB::setClientCallTimeout(15000);
}

void TestManagerJoin::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    m_dir = std::make_unique<QTemporaryDir>();
    m_port = LiveTest::freePort();
    QString error;
    QProcess *master = m_live->startManager(
        RTMANAGER_PATH, m_port,
        {"naming.enable=NO", "manager.components.precreate=ConsoleIn"}, &error);
    QVERIFY2(master, qPrintable(error));
    CORBA::Object_var object
        = m_orb->string_to_object(LiveTest::managerLocation(m_port).constData());
    m_master = RTM::Manager::_narrow(object);
    QVERIFY(!CORBA::is_nil(m_master));
}

void TestManagerJoin::cleanup()
{
    m_master = RTM::Manager::_nil();
    m_live.reset();
    m_dir.reset();
}

void TestManagerJoin::cleanupTestCase()
{
    m_orb->destroy();
}

QStringList TestManagerJoin::slaveNames()
{
    QStringList names;
    RTM::ManagerList_var slaves = m_master->get_slave_managers();
    for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
        RTM::ManagerProfile_var profile = slaves[i]->get_profile();
        names << nv(profile->properties, "instance_name");
        RTM::ManagerList_var masters = slaves[i]->get_master_managers();
        if (masters->length() != 1 || !Runtime::sameObject(masters[0], m_master))
            names.last() += QStringLiteral(" (does not know its master)");
    }
    names.sort();
    return names;
}

RTM::Manager_ptr TestManagerJoin::startOwnMaster(QProcess &process)
{
    const quint16 port = LiveTest::freePort();
    process.start(
        RTMANAGER_PATH,
        {"-d", "-o", QString("corba.endpoints=127.0.0.1:%1").arg(port), "-o", "naming.enable=NO"});
    if (!process.waitForStarted(10000))
        return RTM::Manager::_nil();
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    RTM::Manager_var manager = RTM::Manager::_unchecked_narrow(object);
    // Ready when the manager answers, not merely when its port accepts connections.
    const QDeadlineTimer deadline(10000);
    while (!deadline.hasExpired()) {
        try {
            manager->is_master();
            return manager._retn();
        } catch (const CORBA::Exception &) {
            QTest::qWait(10);
        }
    }
    return RTM::Manager::_nil();
}

void TestManagerJoin::slavesStartedAtOnceAllJoin()
{
    // Slaves started on their own (as on a robot's host) find the master while it is busy
    // aggregating its slaves' components for another client.
    Hammer hammer(m_master);
    std::vector<QProcess *> slaves;
    QStringList expected;
    for (int i = 0; i < SlaveCount; ++i) {
        auto *slave = new QProcess(this);
        const QString name = QStringLiteral("joiner%1").arg(i);
        slave->setStandardErrorFile(m_dir->filePath(name + ".err"));
        slave->start(RTMANAGER_PATH,
                     {"-o", QString("corba.master_manager=127.0.0.1:%1").arg(m_port), "-o",
                      QString("corba.endpoints=127.0.0.1:%1").arg(LiveTest::freePort()), "-o",
                      "naming.enable=NO", "-o", "manager.instance_name=" + name});
        slaves.push_back(slave);
        expected << name;
    }
    // A slave prints its ready line once its join has been answered, either way.
    for (QProcess *slave : slaves) {
        QByteArray output;
        QDeadlineTimer deadline(20000);
        while (!output.contains("rtmanager ready") && !deadline.hasExpired()
               && slave->waitForReadyRead(int(qMax<qint64>(1, deadline.remainingTime()))))
            output += slave->readAllStandardOutput();
        QVERIFY2(output.contains("rtmanager ready"), output.constData());
    }
    QCOMPARE(slaveNames(), expected);
    QVERIFY(hammer.calls() > 0);
    for (int i = 0; i < SlaveCount; ++i) {
        slaves[size_t(i)]->kill();
        slaves[size_t(i)]->waitForFinished(10000);
        QFile err(m_dir->filePath(expected.at(i) + ".err"));
        QVERIFY(err.open(QIODevice::ReadOnly));
        const QByteArray text = err.readAll();
        QVERIFY2(!text.contains("cannot join"), text.constData());
    }
}

void TestManagerJoin::spawnedSlavesHaveJoinedWhenCreateReturns()
{
    // The master's own process writes to a file its slaves inherit, so that what they print after
    // the master is gone is kept too.
    QProcess master;
    const QString errFile = m_dir->filePath("master.err");
    master.setStandardErrorFile(errFile);
    RTM::Manager_var manager = startOwnMaster(master);
    QVERIFY(!CORBA::is_nil(manager));

    Hammer hammer(manager);
    std::vector<std::thread> creators;
    std::atomic_int created {0};
    std::vector<QString> failures(SlaveCount);
    for (int i = 0; i < SlaveCount; ++i) {
        creators.emplace_back([&manager, &created, &failures, i] {
            const QByteArray request = QString("ConsoleOut?manager_name=spawned%1").arg(i).toUtf8();
            try {
                RTC::RTObject_var component = manager->create_component(request.constData());
                if (!CORBA::is_nil(component))
                    ++created;
                else
                    failures[size_t(i)] = QString::fromUtf8(request) + QStringLiteral(": nil");
            } catch (const CORBA::Exception &e) {
                failures[size_t(i)] = QString::fromUtf8(request) + QStringLiteral(": ")
                    + QString::fromLatin1(e._name());
            }
        });
    }
    for (std::thread &creator : creators)
        creator.join();
    QStringList failed;
    for (const QString &failure : failures)
        if (!failure.isEmpty())
            failed << failure;
    QVERIFY2(failed.isEmpty(), qPrintable(failed.join(QStringLiteral("; "))));
    QCOMPARE(created.load(), SlaveCount);
    // Each slave knows its master at once, with no wait, since create_component returned.
    std::vector<pid_t> pids;
    RTM::ManagerList_var slaves = manager->get_slave_managers();
    QCOMPARE(slaves->length(), CORBA::ULong(SlaveCount));
    for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
        RTM::ManagerList_var masters = slaves[i]->get_master_managers();
        QCOMPARE(masters->length(), CORBA::ULong(1));
        pids.push_back(pid_t(
            nv(RTM::ManagerProfile_var(slaves[i]->get_profile())->properties, "pid").toInt()));
    }
    // The master goes down right away; its slaves follow it without having reported a failed join.
    master.kill();
    QVERIFY(master.waitForFinished(10000));
    for (pid_t pid : pids)
        QTRY_VERIFY_WITH_TIMEOUT(gone(pid), 10000);
    QFile err(errFile);
    QVERIFY(err.open(QIODevice::ReadOnly));
    const QByteArray text = err.readAll();
    QVERIFY2(!text.contains("cannot join"), text.constData());
}

void TestManagerJoin::slavesStartThroughForkServer()
{
    QProcess master;
    RTM::Manager_var manager = startOwnMaster(master);
    QVERIFY(!CORBA::is_nil(manager));
    const auto slavePid = [&manager](const char *name) {
        RTC::RTObject_var component
            = manager->create_component(QByteArray("ConsoleOut?manager_name=") + name);
        if (CORBA::is_nil(component))
            return pid_t(0);
        RTM::ManagerList_var slaves = manager->get_slave_managers();
        for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
            RTM::ManagerProfile_var profile = slaves[i]->get_profile();
            if (nv(profile->properties, "instance_name") == QLatin1String(name))
                return pid_t(nv(profile->properties, "pid").toInt());
        }
        return pid_t(0);
    };

    // The slave is a child of the master's fork server and shows its own command line.
    const pid_t forked = slavePid("forked");
    QVERIFY(forked > 0);
    const pid_t server = parentOf(forked);
    QCOMPARE(parentOf(server), pid_t(master.processId()));
    QVERIFY2(commandLine(server).startsWith("rtmanager --fork-server"), commandLine(server).constData());
    const QByteArray shown = commandLine(forked);
    QVERIFY2(shown.startsWith("rtmanager -o ") && shown.contains("manager.instance_name=forked")
                 && !shown.contains("--fork-server"),
             shown.constData());

    // Without its fork server (killed), the master starts slaves itself; the server's slaves end.
    QCOMPARE(::kill(server, SIGKILL), 0);
    QTRY_VERIFY_WITH_TIMEOUT(gone(forked), 10000);
    const pid_t direct = slavePid("direct");
    QVERIFY(direct > 0);
    QCOMPARE(parentOf(direct), pid_t(master.processId()));

    master.kill();
    QVERIFY(master.waitForFinished(10000));
    QTRY_VERIFY_WITH_TIMEOUT(gone(direct), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(gone(server), 10000);
}

QTEST_GUILESS_MAIN(TestManagerJoin)
#include "tst_managerjoin.moc"
