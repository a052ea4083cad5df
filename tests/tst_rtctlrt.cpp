// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

#include "livesystem.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

// rtctl's rtshell commands run as a user would, against omniNames and a live peer process.
class TestRtctlRt : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void lsListsTheTree();
    void lsLongFormAndJson();
    void lsRecursiveAndRoot();
    void catShowsComponentsPortsAndManagers();
    void findFiltersByNameAndType();
    void pwdAndCd();
    void stateCommands();
    void connectAndDisconnect();
    void configuration();
    void manager();
    void exitRemovesAComponent();
    void usageErrors_data();
    void usageErrors();
    void unreachableServerIsAFailure();
    void drivesTheRealManager();
    void forkAndRestartTheRealManager();
    void namedCreatesRunSideBySide();
    void pathsBelowAManager();

private:
    using Result = RtctlResult;
    Result rtctl(const QStringList &arguments, const QString &cwd = QString(),
                 const QString &servers = QString());
    bool startRealManager(quint16 port, const QString &hostName, const QString &precreate,
                          QString *error);
    QString host() const
    {
        return QStringLiteral("/%1/rthost.host_cxt").arg(m_live.namingServer());
    }

    LiveTest::LiveSystem m_live;
    quint16 m_peerPort = 0;
};

TestRtctlRt::Result TestRtctlRt::rtctl(const QStringList &arguments, const QString &cwd,
                                       const QString &servers)
{
    return runRtctl(arguments,
                    {{QStringLiteral("RTCSH_CWD"), cwd.isNull() ? host() : cwd},
                     {QStringLiteral("RTCTREE_NAMESERVERS"), servers}});
}

// An rtmanager master on `port`, its components and itself registered under `hostName`.host_cxt.
bool TestRtctlRt::startRealManager(quint16 port, const QString &hostName, const QString &precreate,
                                   QString *error)
{
    const QStringList options {"corba.nameservers=" + m_live.namingServer(),
                               "naming.formats=" + hostName + ".host_cxt/%n.rtc",
                               "manager.naming_formats=" + hostName + ".host_cxt/%n.mgr",
                               "manager.components.precreate=" + precreate};
    return m_live.startManager(RTMANAGER_PATH, port, options, error) != nullptr;
}

void TestRtctlRt::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    QVERIFY2(m_live.startPeer({"ConsoleIn?instance_name=ConsoleIn0",
                               "ConsoleOut?instance_name=ConsoleOut0",
                               "MyServiceProvider?instance_name=Provider0",
                               "ConfigSample?instance_name=ConfigSample0"},
                              &error, &m_peerPort, "rthost", true),
             qPrintable(error));
}

void TestRtctlRt::lsListsTheTree()
{
    const Result r = rtctl({"ls"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.lines(),
             QStringList({"manager.mgr", "ConsoleIn0.rtc", "ConsoleOut0.rtc", "Provider0.rtc",
                          "ConfigSample0.rtc", "*Ghost0.rtc", "*Stranger0.rtc"}));
    const Result server = rtctl({"ls", "/" + m_live.namingServer()});
    QCOMPARE(server.lines(), QStringList({"rthost.host_cxt"}));
    QCOMPARE(rtctl({"ls", ".."}, host() + "/manager.mgr").lines(), r.lines());
}

void TestRtctlRt::lsLongFormAndJson()
{
    const Result r = rtctl({"ls", "-l", "ConsoleIn0.rtc", "Ghost0.rtc"});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.lines();
    QCOMPARE(lines.size(), 2);
    QCOMPARE(lines[0].simplified(), QString("Inactive 1/0 0/0 1/0 0/0 ConsoleIn0.rtc"));
    QCOMPARE(lines[1].simplified(), QString("- - - - - *Ghost0.rtc"));

    const Result json = rtctl({"ls", "-l", "--json"});
    QCOMPARE(json.code, 0);
    const QJsonArray entries = json.json().array();
    QCOMPARE(entries.size(), 7);
    QCOMPARE(entries[1]["name"].toString(), QString("ConsoleIn0.rtc"));
    QCOMPARE(entries[1]["type"].toString(), QString("component"));
    QCOMPARE(entries[1]["state"].toString(), QString("Inactive"));
    QCOMPARE(entries[1]["ports"]["out"].toInt(), 1);
    QCOMPARE(entries[5]["type"].toString(), QString("zombie"));
    QVERIFY(entries[5]["reason"].toString().contains("Ghost0.rtc"));
}

void TestRtctlRt::lsRecursiveAndRoot()
{
    const Result r = rtctl({"ls", "-R", "/" + m_live.namingServer()});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains(host() + "/manager.mgr:\nConsoleIn0.rtc\n"), qPrintable(r.out));
    const Result root = rtctl({"ls", "/"}, "/", m_live.namingServer());
    QCOMPARE(root.lines(), QStringList({m_live.namingServer()}));
    const Result tree = rtctl({"ls", "-R", "--json", "/"}, "/", m_live.namingServer());
    const QJsonArray servers = tree.json().array();
    QCOMPARE(servers.size(), 1);
    QCOMPARE(servers[0]["children"][0]["name"].toString(), QString("rthost.host_cxt"));
    QCOMPARE(servers[0]["children"][0]["children"].toArray().size(), 7);
}

void TestRtctlRt::catShowsComponentsPortsAndManagers()
{
    const Result r = rtctl({"cat", "ConsoleIn0.rtc"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.lines().at(0).startsWith("ConsoleIn0.rtc  Inactive"));
    QVERIFY(r.lines().contains("  Type name      ConsoleIn"));
    QVERIFY(r.lines().contains("  DataOutPort: out"));
    QVERIFY(!r.out.contains("dataport.data_type"));
    QVERIFY(rtctl({"cat", "-l", "ConsoleIn0.rtc"})
                .out.contains("dataport.data_type = IDL:RTC/TimedLong:1.0"));

    const Result port = rtctl({"cat", "Provider0.rtc:MyService"});
    QCOMPARE(port.code, 0);
    QCOMPARE(port.lines(),
             QStringList({"  CorbaPort: MyService",
                          "    Interface  myservice  SimpleService::MyService  Provided"}));
    const Result json = rtctl({"cat", "--json", "ConsoleIn0.rtc"});
    QCOMPARE(json.json().object()["typeName"].toString(), QString("ConsoleIn"));
    QCOMPARE(json.json().object()["executionContexts"][0]["kind"].toString(), QString("PERIODIC"));
    QCOMPARE(json.json().object()["ports"][0]["type"].toString(), QString("DataOutPort"));

    const Result missing = rtctl({"cat", "ConsoleIn0.rtc:nothere"});
    QCOMPARE(missing.code, 1);
    QVERIFY2(missing.err.contains(host() + "/ConsoleIn0.rtc: no port named 'nothere'"),
             qPrintable(missing.err));
    const Result manager = rtctl({"cat", "manager.mgr"});
    QCOMPARE(manager.code, 0);
    QVERIFY(manager.lines().contains("  Component  ConfigSample0  ConfigSample"));
    const QJsonObject managerJson = rtctl({"cat", "--json", "manager.mgr"}).json().object();
    QCOMPARE(managerJson["profile"]["instance_name"].toString(), QString("manager"));
    QVERIFY(managerJson["components"].toArray().contains(QJsonValue("ConsoleIn0")));
}

void TestRtctlRt::findFiltersByNameAndType()
{
    const Result zombies = rtctl({"find", host(), "-t", "z"});
    QCOMPARE(zombies.code, 0);
    QCOMPARE(zombies.lines(), QStringList({host() + "/Ghost0.rtc", host() + "/Stranger0.rtc"}));
    const Result named = rtctl({"find", host(), "-i", "console*", "-m", "1"});
    QCOMPARE(named.lines(), QStringList({host() + "/ConsoleIn0.rtc", host() + "/ConsoleOut0.rtc"}));
    QVERIFY(rtctl({"find", host(), "-n", "console*"}).lines().isEmpty());
    const Result json = rtctl({"find", "--json", host(), "-t", "m"});
    QCOMPARE(json.json().array().at(0)["path"].toString(), host() + "/manager.mgr");
}

void TestRtctlRt::pwdAndCd()
{
    QCOMPARE(rtctl({"pwd"}).out, host() + "\n");
    QCOMPARE(rtctl({"pwd"}, "").out, QString("/\n"));
    const Result cd = rtctl({"cd", ".."});
    QCOMPARE(cd.code, 0);
    QCOMPARE(cd.out, QStringLiteral("export RTCSH_CWD='/%1'\n").arg(m_live.namingServer()));
    QCOMPARE(rtctl({"cd", "manager.mgr"}).code, 0);
    const Result notDir = rtctl({"cd", "ConsoleIn0.rtc"});
    QCOMPARE(notDir.code, 1);
    QVERIFY(notDir.err.contains("ConsoleIn0.rtc: not a directory"));
    QCOMPARE(rtctl({"cd", "Nothing.host_cxt"}).code, 1);
}

void TestRtctlRt::stateCommands()
{
    QCOMPARE(rtctl({"act", "ConsoleOut0.rtc"}).code, 0);
    QVERIFY(rtctl({"ls", "-l", "ConsoleOut0.rtc"}).out.startsWith("Active"));
    const Result again = rtctl({"act", "-e", "0", "ConsoleOut0.rtc"});
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains("ConsoleOut0.rtc: activate returned PRECONDITION_NOT_MET"),
             qPrintable(again.err));
    QCOMPARE(rtctl({"reset", "ConsoleOut0.rtc"}).code, 1);
    QCOMPARE(rtctl({"act", "-e", "3", "ConsoleIn0.rtc"}).code, 1);
    QCOMPARE(rtctl({"deact", "ConsoleOut0.rtc"}).code, 0);
    QVERIFY(rtctl({"ls", "-l", "ConsoleOut0.rtc"}).out.startsWith("Inactive"));
    // Several paths: the good one is done, the zombie is reported, the exit code says failure.
    const Result mixed = rtctl({"act", "ConsoleIn0.rtc", "Ghost0.rtc"});
    QCOMPARE(mixed.code, 1);
    QVERIFY(mixed.err.contains("Ghost0.rtc: unreachable"));
    QVERIFY(rtctl({"ls", "-l", "ConsoleIn0.rtc"}).out.startsWith("Active"));
    QCOMPARE(rtctl({"deact", "ConsoleIn0.rtc"}).code, 0);
    QCOMPARE(rtctl({"act", "manager.mgr"}).code, 1);
}

void TestRtctlRt::connectAndDisconnect()
{
    const Result con = rtctl({"con", "-n", "link", "-p", "dataport.subscription_type=flush",
                              "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"});
    QCOMPARE(con.code, 0);
    const QString id = con.out.trimmed();
    QVERIFY(!id.isEmpty());
    const QJsonObject port = rtctl({"cat", "--json", "ConsoleOut0.rtc:in"}).json().object();
    QCOMPARE(port["connectors"][0]["id"].toString(), id);
    QCOMPARE(port["connectors"][0]["name"].toString(), QString("link"));
    QCOMPARE(port["connectors"][0]["properties"]["dataport.subscription_type"].toString(),
             QString("flush"));

    const Result duplicate
        = rtctl({"con", "--no-duplicates", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"});
    QCOMPARE(duplicate.code, 1);
    QVERIFY(duplicate.err.contains("already connected"));
    const Result illegal = rtctl({"con", "ConsoleOut0.rtc:in", "ConsoleOut0.rtc:in"});
    QCOMPARE(illegal.code, 1);
    QVERIFY2(illegal.err.contains("cannot connect: ConsoleOut0.in is not an output port"),
             qPrintable(illegal.err));
    const Result badFlow = rtctl(
        {"con", "-p", "dataport.dataflow_type=duplex", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"});
    QCOMPARE(badFlow.code, 1);
    QVERIFY(badFlow.err.contains("does not allow dataport.dataflow_type=duplex"));
    QCOMPARE(rtctl({"con", "ConsoleIn0.rtc:out", "Provider0.rtc:MyService"}).code, 1);

    QCOMPARE(rtctl({"dis", "-i", "wrong", "ConsoleIn0.rtc:out"}).code, 1);
    QCOMPARE(rtctl({"dis", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}).code, 0);
    QVERIFY(rtctl({"cat", "--json", "ConsoleOut0.rtc:in"})
                .json()
                .object()["connectors"]
                .toArray()
                .isEmpty());
    QCOMPARE(rtctl({"dis", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}).code, 1);
    // By id, then all of a component.
    const QString second
        = rtctl({"con", "-i", "my-id", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}).out.trimmed();
    QCOMPARE(second, QString("my-id"));
    QCOMPARE(rtctl({"dis", "-i", "my-id", "ConsoleOut0.rtc:in"}).code, 0);
    QCOMPARE(rtctl({"con", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}).code, 0);
    QCOMPARE(rtctl({"dis", "ConsoleOut0.rtc"}).code, 0);
    QVERIFY(rtctl({"ls", "-l", "ConsoleIn0.rtc"}).out.simplified().startsWith("Inactive 1/0"));
}

void TestRtctlRt::configuration()
{
    const Result list = rtctl({"conf", "ConfigSample0.rtc"});
    QCOMPARE(list.code, 0);
    QVERIFY(list.lines().contains("* default"));
    QVERIFY(list.lines().contains("  mode0"));
    QVERIFY(!list.out.contains("__widget__"));
    QVERIFY(rtctl({"conf", "-a", "ConfigSample0.rtc"}).out.contains("  __widget__"));

    QCOMPARE(rtctl({"conf", "ConfigSample0.rtc", "set", "int_param0", "77"}).code, 0);
    QCOMPARE(rtctl({"conf", "ConfigSample0.rtc", "get", "int_param0"}).out, QString("77\n"));
    QCOMPARE(rtctl({"conf", "-s", "mode0", "ConfigSample0.rtc", "get", "str_param0"}).out,
             QString("foo\n"));
    const Result missing = rtctl({"conf", "ConfigSample0.rtc", "get", "nothing"});
    QCOMPARE(missing.code, 1);
    QVERIFY(missing.err.contains("no parameter 'nothing' in set 'default'"));

    QCOMPARE(rtctl({"conf", "-s", "mode0", "ConfigSample0.rtc", "act"}).code, 0);
    const QJsonObject json = rtctl({"conf", "--json", "ConfigSample0.rtc"}).json().object();
    QCOMPARE(json["active"].toString(), QString("mode0"));
    QCOMPARE(json["sets"][0]["parameters"]["int_param0"].toString(), QString("77"));
    QCOMPARE(rtctl({"conf", "-s", "default", "ConfigSample0.rtc", "act"}).code, 0);
    QCOMPARE(rtctl({"conf", "-s", "nothing", "ConfigSample0.rtc", "act"}).code, 1);
}

void TestRtctlRt::manager()
{
    const Result created = rtctl({"mgr", "manager.mgr", "create", "ConsoleOut?instance_name=Made0",
                                  "load", "mods/Foo.so:FooInit", "list"});
    QCOMPARE(created.code, 0);
    QCOMPARE(created.lines().at(0), QString("Made0"));
    QVERIFY(created.lines().contains("  Made0  ConsoleOut"));
    QVERIFY(created.lines().contains("  mods/Foo.so"));
    QVERIFY(rtctl({"ls"}).lines().contains("Made0.rtc"));

    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_peerPort);
    const Result json = rtctl({"mgr", "--json", direct, "list"});
    QCOMPARE(json.code, 0);
    QCOMPARE(json.json().object()["components"].toArray().size(), 5);
    QCOMPARE(rtctl({"mgr", direct, "delete", "Made0", "unload", "mods/Foo.so"}).code, 0);
    QVERIFY(!rtctl({"ls"}).lines().contains("Made0.rtc"));
    const Result again = rtctl({"mgr", direct, "-d", "Made0"});
    QCOMPARE(again.code, 1);
    QVERIFY(again.err.contains("delete_component(Made0) returned BAD_PARAMETER"));
    QCOMPARE(rtctl({"mgr", "ConsoleIn0.rtc", "list"}).code, 1);

    // Creates an OpenRTM-aist manager (the peer) hosts are made one by one: it has no
    // create_components.
    const Result two = rtctl(
        {"mgr", direct, "create", "ConsoleOut?instance_name=Made1", "create", "ConsoleOut"});
    QCOMPARE(two.code, 0);
    QCOMPARE(two.lines(), QStringList({"Made1", "ConsoleOut1"}));
    QVERIFY(rtctl({"ls"}).lines().contains("ConsoleOut1.rtc"));
    QCOMPARE(rtctl({"mgr", direct, "delete", "Made1", "delete", "ConsoleOut1"}).code, 0);
}

void TestRtctlRt::exitRemovesAComponent()
{
    QString error;
    QVERIFY2(m_live.startPeer({"ConsoleIn?instance_name=Bye0"}, &error, nullptr, "byehost"),
             qPrintable(error));
    const QString path = QStringLiteral("/%1/byehost.host_cxt/Bye0.rtc").arg(m_live.namingServer());
    QCOMPARE(rtctl({"exit", path}).code, 0);
    const Result gone = rtctl({"cat", path});
    QCOMPARE(gone.code, 1);
    QVERIFY2(gone.err.contains(path + ": no such name"), qPrintable(gone.err));
}

void TestRtctlRt::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("act without path") << QStringList {"act"};
    QTest::newRow("unknown flag") << QStringList {"ls", "-x"};
    QTest::newRow("bad timeout") << QStringList {"ls", "--timeout", "soon"};
    QTest::newRow("bad ec index") << QStringList {"act", "-e", "first", "ConsoleIn0.rtc"};
    QTest::newRow("con one port") << QStringList {"con", "ConsoleIn0.rtc:out"};
    QTest::newRow("con bad property") << QStringList {"con", "-p", "novalue", "a.rtc:x", "b.rtc:y"};
    QTest::newRow("conf unknown") << QStringList {"conf", "ConfigSample0.rtc", "frob"};
    QTest::newRow("conf act without set") << QStringList {"conf", "ConfigSample0.rtc", "act"};
    QTest::newRow("mgr unknown action") << QStringList {"mgr", "manager.mgr", "explode"};
    QTest::newRow("mgr missing argument") << QStringList {"mgr", "manager.mgr", "create"};
    QTest::newRow("find bad type") << QStringList {"find", "/", "-t", "q"};
    QTest::newRow("pwd with argument") << QStringList {"pwd", "x"};
}

void TestRtctlRt::usageErrors()
{
    QFETCH(QStringList, arguments);
    const Result r = rtctl(arguments);
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("Usage:"));
}

void TestRtctlRt::unreachableServerIsAFailure()
{
    const QString nowhere = QStringLiteral("/127.0.0.1:%1").arg(LiveTest::freePort());
    const Result r = rtctl({"ls", "--timeout", "1000", nowhere});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(nowhere + ": unreachable"), qPrintable(r.err));
    const Result bad = rtctl({"cat", "/127.0.0.1:x/a.rtc"});
    QCOMPARE(bad.code, 1);
    QVERIFY(bad.err.contains("bad name server address"));

    // A manager given by address is used without asking first what it is: its first call tells
    // that nothing listens there, or that what listens (here the name server) has no manager.
    const Result noManager = rtctl(
        {"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(LiveTest::freePort()), "list"});
    QCOMPARE(noManager.code, 1);
    QVERIFY2(noManager.err.contains("/manager: unreachable (cannot connect)"),
             qPrintable(noManager.err));
    for (const QStringList &actions : {QStringList {"list"},
                                       QStringList {"create", "ConsoleIn?instance_name=x", "create",
                                                    "ConsoleIn?instance_name=y"}}) {
        const Result notAManager = rtctl(
            QStringList {"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_live.namingPort())}
            + actions);
        QCOMPARE(notAManager.code, 1);
        QVERIFY2(
            notAManager.err.contains(QStringLiteral("127.0.0.1:%1/manager: object does not exist")
                                         .arg(m_live.namingPort())),
            qPrintable(notAManager.err));
    }
}

// The same commands against the project's rtmanager process instead of the test peer.
void TestRtctlRt::drivesTheRealManager()
{
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(startRealManager(port, "realhost", "ConsoleIn,ConsoleOut", &error), qPrintable(error));
    const QString dir = QStringLiteral("/%1/realhost.host_cxt").arg(m_live.namingServer());
    const Result ls = rtctl({"ls"}, dir);
    QCOMPARE(ls.code, 0);
    QCOMPARE(ls.lines().size(), 3);
    QVERIFY(ls.lines().contains("ConsoleIn0.rtc"));
    const Result con = rtctl({"con", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}, dir);
    QCOMPARE(con.code, 0);
    // A second connection between the same ports: the port refuses it, as OpenRTM-aist's do, and
    // rtctl says why and how to ask for it.
    const Result again = rtctl({"con", "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"}, dir);
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains(
                 "connect returned PRECONDITION_NOT_MET: ConsoleIn0.out is already connected to "
                 "ConsoleOut0.in (connector "
                 + con.out.trimmed() + ")")
                 && again.err.contains("dataport.allow_dup_connection=YES"),
             qPrintable(again.err));
    const Result allowed = rtctl({"con", "-p", "dataport.allow_dup_connection=YES",
                                  "ConsoleIn0.rtc:out", "ConsoleOut0.rtc:in"},
                                 dir);
    QCOMPARE(allowed.code, 0);
    QCOMPARE(rtctl({"dis", "-i", allowed.out.trimmed(), "ConsoleOut0.rtc:in"}, dir).code, 0);
    QCOMPARE(rtctl({"act", "ConsoleIn0.rtc", "ConsoleOut0.rtc"}, dir).code, 0);
    QTRY_VERIFY(
        rtctl({"ls", "-l", "ConsoleOut0.rtc"}, dir).out.simplified().startsWith("Active 1/1 1/1"));
    QCOMPARE(rtctl({"deact", "ConsoleIn0.rtc", "ConsoleOut0.rtc"}, dir).code, 0);
    QCOMPARE(rtctl({"dis", "ConsoleIn0.rtc"}, dir).code, 0);
    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    const Result created
        = rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Late0", "list"}, dir);
    QCOMPARE(created.code, 0);
    QCOMPARE(created.lines().at(0), QString("Late0"));
    QVERIFY(rtctl({"ls"}, dir).lines().contains("Late0.rtc"));
    QCOMPARE(rtctl({"mgr", direct, "delete", "Late0"}, dir).code, 0);
}

// rtshell's style: silent on success; on a refusal exit code 1 and the manager's own reason.
void TestRtctlRt::forkAndRestartTheRealManager()
{
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(startRealManager(port, "forkhost", "ConsoleIn", &error), qPrintable(error));
    const QString dir = QStringLiteral("/%1/forkhost.host_cxt").arg(m_live.namingServer());
    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    const Result forked = rtctl({"mgr", direct, "fork"}, dir);
    QCOMPARE(forked.code, 0);
    QCOMPARE(forked.out, QString());
    QCOMPARE(forked.err, QString());
    // fork returns once the new slave has joined: it is listed under the master at once.
    QCOMPARE(rtctl({"ls", "manager.mgr"}, dir).lines(),
             QStringList({"ConsoleIn0.rtc", "slave0.mgr"}));

    QCOMPARE(rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Gone0"}, dir).code, 0);
    const Result restarted = rtctl({"mgr", direct, "restart"}, dir);
    QCOMPARE(restarted.code, 0);
    QCOMPARE(restarted.out, QString());
    // The same endpoint answers again, fresh: the precreated component only, its slave gone.
    QTRY_COMPARE_WITH_TIMEOUT(rtctl({"ls", "manager.mgr"}, dir).lines(),
                              QStringList({"ConsoleIn0.rtc"}), 15000);

    // A manager with neither master role nor master to register a sibling with refuses to fork.
    const quint16 lonePort = LiveTest::freePort();
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH,
                            {"-o", QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(lonePort),
                             "-o", "corba.master_manager=", "-o", "naming.enable=NO"},
                            "rtmanager ready", &error),
        qPrintable(error));
    const Result refused
        = rtctl({"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(lonePort), "fork"}, dir);
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains("fork returned BAD_PARAMETER (fork: this manager has no master"),
             qPrintable(refused.err));
    // A module it cannot load, or one not loaded: the manager's reason, not only the return code.
    const QString lone = QStringLiteral("corbaloc::127.0.0.1:%1").arg(lonePort);
    const Result load = rtctl({"mgr", lone, "load", "/nonexistent/Missing.so"}, dir);
    QCOMPARE(load.code, 1);
    QVERIFY2(load.err.contains("returned BAD_PARAMETER (load_module: no module file '/nonexistent/Missing.so')"),
             qPrintable(load.err));
    const Result unload = rtctl({"mgr", lone, "unload", "Missing.so"}, dir);
    QCOMPARE(unload.code, 1);
    QVERIFY2(unload.err.contains("(unload_module: 'Missing.so' is not loaded)"), qPrintable(unload.err));
}

// Creates naming their own instances are sent at once; the output and the outcome stay those of
// one create after the other.
void TestRtctlRt::namedCreatesRunSideBySide()
{
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(startRealManager(port, "sidehost", "", &error), qPrintable(error));
    const QString dir = QStringLiteral("/%1/sidehost.host_cxt").arg(m_live.namingServer());
    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    QStringList arguments {"mgr", direct};
    QStringList expected;
    for (int i = 0; i < 6; ++i) {
        const QString name = QStringLiteral("Side%1").arg(i);
        // Every other one in a slave process of its own, started side by side too.
        arguments << "create"
                  << QStringLiteral("ConsoleOut?instance_name=%1%2")
                         .arg(name, i % 2 ? QStringLiteral("&manager_name=manager_%p") : QString());
        expected << name;
    }
    // Unnamed ones are numbered in order, as one after the other would number them.
    arguments << "create" << "ConsoleIn" << "create" << "ConsoleIn";
    expected << "ConsoleIn0" << "ConsoleIn1";
    const Result created = rtctl(arguments, dir);
    QCOMPARE(created.code, 0);
    QCOMPARE(created.lines(), expected);
    const QStringList listed = rtctl({"ls", "-R", "."}, dir).out.split(QRegularExpression("\\s+"));
    for (const QString &name : std::as_const(expected))
        QVERIFY2(listed.contains(name + ".rtc"), qPrintable(name));

    // Refused side by side, each for a name of its own: the first refusal is the one reported,
    // with its own reason.
    const Result taken = rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Side0", "create",
                                "ConsoleOut?instance_name=Side2", "create", "ConsoleOut?instance_name=Side4"},
                               dir);
    QCOMPARE(taken.code, 1);
    QVERIFY2(taken.err.contains("'Side0' is already in use") && !taken.err.contains("Side2"),
             qPrintable(taken.err));
    // The same for refusals of one slave: the master reads the slave's reason by request too.
    QStringList twins {"mgr", direct};
    for (int i = 0; i < 4; ++i)
        twins << "create" << QStringLiteral("ConsoleOut?instance_name=Twin%1&manager_name=twinslave").arg(i);
    QCOMPARE(rtctl(twins, dir).code, 0);
    const Result twinsTaken = rtctl(twins, dir);
    QCOMPARE(twinsTaken.code, 1);
    QVERIFY2(twinsTaken.err.contains("'Twin0' is already in use") && !twinsTaken.err.contains("'Twin1'")
                 && !twinsTaken.err.contains("'Twin2'") && !twinsTaken.err.contains("'Twin3'"),
             qPrintable(twinsTaken.err));

    // A failed create stops there: the ones before it are printed, those after it made no more.
    const Result failed = rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Before0", "create",
                                 "NoSuchType?instance_name=Broken0", "create",
                                 "ConsoleOut?instance_name=After0&manager_name=manager_%p", "create",
                                 "ConsoleOut?instance_name=After1"},
                                dir);
    QCOMPARE(failed.code, 1);
    QCOMPARE(failed.lines(), QStringList {"Before0"});
    QVERIFY2(failed.err.contains("NoSuchType"), qPrintable(failed.err));
    const QStringList after = rtctl({"ls", "-R", "."}, dir).out.split(QRegularExpression("\\s+"));
    QVERIFY(after.contains("Before0.rtc"));
    QVERIFY2(!after.contains("After0.rtc") && !after.contains("After1.rtc"), qPrintable(after.join(' ')));
}

// What `ls` lists below a manager (its components, its slaves) is a path every command takes; a
// component in a slave is deleted through its master.
void TestRtctlRt::pathsBelowAManager()
{
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(startRealManager(port, "belowhost", "ConsoleIn", &error), qPrintable(error));
    const QString dir = QStringLiteral("/%1/belowhost.host_cxt").arg(m_live.namingServer());
    const QString direct = QStringLiteral("corbaloc::127.0.0.1:%1").arg(port);
    QCOMPARE(rtctl({"mgr", direct, "create", "ConsoleOut?instance_name=Far0&manager_name=manager_%p"}, dir)
                 .code,
             0);
    QCOMPARE(rtctl({"ls", "manager.mgr/slave0.mgr"}, dir).lines(), QStringList {"Far0.rtc"});
    // A master lists its slaves' components with its own (as OpenRTM-aist's): those paths resolve.
    QCOMPARE(rtctl({"ls", "manager.mgr"}, dir).lines(),
             QStringList({"ConsoleIn0.rtc", "Far0.rtc", "slave0.mgr"}));
    QVERIFY(rtctl({"cat", "manager.mgr/Far0.rtc"}, dir).out.contains("Far0"));
    // `ls -R` goes into the slaves too (rtshell's rtls does), listing what each hosts.
    const QString recursive = rtctl({"ls", "-R", "manager.mgr"}, dir).out;
    QVERIFY2(recursive.contains(QStringLiteral("manager.mgr/slave0.mgr:\nFar0.rtc\n")), qPrintable(recursive));

    const QString far = QStringLiteral("manager.mgr/slave0.mgr/Far0.rtc");
    const Result cat = rtctl({"cat", far}, dir);
    QVERIFY2(cat.code == 0, qPrintable(cat.err));
    QVERIFY2(cat.out.contains("Far0") && cat.out.contains("Inactive"), qPrintable(cat.out));
    QCOMPARE(rtctl({"act", far}, dir).code, 0);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", far}, dir).out.contains("Active"), 10000);
    QCOMPARE(rtctl({"deact", far}, dir).code, 0);
    QVERIFY2(rtctl({"cat", "manager.mgr/ConsoleIn0.rtc"}, dir).out.contains("ConsoleIn0"),
             "a component of the master itself");
    const Result slaveList = rtctl({"mgr", "manager.mgr/slave0.mgr", "list"}, dir);
    QVERIFY2(slaveList.out.contains("  Far0  ConsoleOut"), qPrintable(slaveList.out + slaveList.err));
    QVERIFY2(!slaveList.out.contains("ConsoleIn0"), qPrintable(slaveList.out));

    // Names the manager does not have are not found, with the path.
    const Result noSlave = rtctl({"cat", "manager.mgr/slave7.mgr"}, dir);
    QCOMPARE(noSlave.code, 1);
    QVERIFY2(noSlave.err.contains("manager.mgr/slave7.mgr: no such name"), qPrintable(noSlave.err));
    const Result noComponent = rtctl({"act", "manager.mgr/slave0.mgr/Near0.rtc"}, dir);
    QCOMPARE(noComponent.code, 1);
    QVERIFY2(noComponent.err.contains("slave0.mgr/Near0.rtc: no such name"), qPrintable(noComponent.err));

    // The master does not delete what its slave hosts; rtctl asks the slave and says so.
    const Result deleted = rtctl({"mgr", direct, "delete", "Far0"}, dir);
    QVERIFY2(deleted.code == 0, qPrintable(deleted.err));
    QVERIFY2(deleted.err.contains("Far0 deleted by ") && deleted.err.contains("/slave0.mgr"),
             qPrintable(deleted.err));
    QTRY_VERIFY(!rtctl({"ls", "-R", "."}, dir).out.contains("Far0"));
    const Result missing = rtctl({"mgr", direct, "delete", "Far0"}, dir);
    QCOMPARE(missing.code, 1);
    QVERIFY2(missing.err.contains("delete_component(Far0) returned BAD_PARAMETER"), qPrintable(missing.err));
}

QTEST_GUILESS_MAIN(TestRtctlRt)
#include "tst_rtctlrt.moc"
