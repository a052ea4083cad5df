// SPDX-License-Identifier: MIT
// TLS for a whole system: a certificate authority and certificates made with `rtctl tls`, omniNames,
// an rtmanager master and its slaves serving over TLS only, rtctl and this test calling them with an
// operator's certificate; connections without a certificate, with one of another authority or with
// an expired one refused while they are set up, with the reason; and `rtctl local start --tls`.
#include "componentstatus.h"
#include "livesystem.h"
#include "pythonenvironment.h"
#include "rtctlrunner.h"
#include "simulatedhosts.h"
#include "tlsorb.h"
#include "tlstransport.h"

#include <RTC.hh>

#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <memory>

#include <unistd.h>

namespace {

QString hostName()
{
    char name[256] = {};
    gethostname(name, sizeof name - 1);
    return QString::fromLocal8Bit(name);
}

} // namespace

class TestTls : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void certificatesSayWhatTheyAre();
    void badCertificateFilesAreNamed();
    void systemRunsOverTls();
    void savesAndRestoresOverTls();
    void refusedPeers_data();
    void refusedPeers();
    void plainClientGetsNoService();
    void connectionLimitCountsTlsConnections();
    void dataFlowsBetweenTwoHosts();
    void localRuntimeWithTls();
    void openRtmTlsConfigurationServes();
    void pythonComponentOverTls();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }
    RtctlResult rtctl(const QStringList &arguments, const QString &ca, const QString &key = {}) const;
    RtctlResult operatorRtctl(const QStringList &arguments) const
    {
        return rtctl(arguments, path("fleet/ca.pem"), path("fleet/operator.pem"));
    }
    bool startMaster(QString *error);
    /// A TLS master of its own on @p port with @p options added, its standard error read with its output.
    QProcess *startTlsManager(quint16 port, const QStringList &options, QString *error);
    /// What the master printed so far.
    QString masterOutput();

    QTemporaryDir m_dir {QDir::tempPath() + QStringLiteral("/rttlsXXXXXX")};
    LiveTest::LiveSystem m_live;
    QProcess *m_master = nullptr;
    QString m_masterOutput;
    quint16 m_masterPort = 0;
    CORBA::ORB_var m_orb;
};

RtctlResult TestTls::rtctl(const QStringList &arguments, const QString &ca, const QString &key) const
{
    // No local runtime of the user's: only what is given here.
    return runRtctl(arguments, {{"RTSTUDIO_TLS_CA", ca}, {"RTSTUDIO_TLS_KEY", key},
                                {"XDG_RUNTIME_DIR", m_dir.filePath(QStringLiteral("runtime"))}});
}

void TestTls::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("runtime")));
    QFile::setPermissions(m_dir.filePath(QStringLiteral("runtime")),
                          QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    if (QStandardPaths::findExecutable(QStringLiteral("openssl")).isEmpty())
        QFAIL("openssl is not installed (Debian package openssl)");

    // One authority for the fleet, a certificate for the node and one for the operator; another
    // authority and its own certificate; an operator's certificate that expires at once.
    const QList<QStringList> steps {
        {"tls", "init", path("fleet"), "--name", "Fleet CA"},
        {"tls", "issue", path("fleet"), "node", "--host", "127.0.0.1"},
        {"tls", "issue", path("fleet"), "operator"},
        {"tls", "issue", path("fleet"), "former", "--days", "0"},
        {"tls", "init", path("other"), "--name", "Other CA"},
        {"tls", "issue", path("other"), "intruder"},
    };
    QString made;
    QVERIFY2(runRtctlAll(steps, &made), qPrintable(made));

    QString error;
    QVERIFY2(m_live.startTlsNameServer(path("fleet/ca.pem"), path("fleet/node.pem"), &error), qPrintable(error));
    QVERIFY2(startMaster(&error), qPrintable(error));

    // This test calls the components too, as the operator.
    std::string reason;
    m_orb = LiveTest::initOrb("tst_tls", {path("fleet/ca.pem").toStdString(), path("fleet/operator.pem").toStdString(), {}},
                              &reason);
    QVERIFY2(!CORBA::is_nil(m_orb), reason.c_str());
}

void TestTls::cleanupTestCase()
{
    runRtctl({"local", "stop"}, {{"XDG_RUNTIME_DIR", m_dir.filePath(QStringLiteral("runtime"))}});
    m_live.stopAll();
    if (!CORBA::is_nil(m_orb))
        m_orb->destroy();
}

QProcess *TestTls::startTlsManager(quint16 port, const QStringList &options, QString *error)
{
    m_live.setErrorsRead(true);
    return m_live.startManager(RTMANAGER_PATH, port,
                               QStringList {QStringLiteral("corba.ssl.certificate_authority_file=") + path("fleet/ca.pem"),
                                            QStringLiteral("corba.ssl.key_file=") + path("fleet/node.pem")}
                                   + options,
                               error);
}

bool TestTls::startMaster(QString *error)
{
    m_masterPort = LiveTest::freePort();
    m_master = startTlsManager(m_masterPort, {QStringLiteral("corba.nameservers=") + m_live.namingServer()}, error);
    return m_master != nullptr;
}

QString TestTls::masterOutput()
{
    m_masterOutput += QString::fromLocal8Bit(m_master->readAll());
    return m_masterOutput;
}

void TestTls::certificatesSayWhatTheyAre()
{
    const RtctlResult shown = runRtctl({"tls", "show", path("fleet/operator.pem"), path("fleet/ca.pem")});
    QVERIFY2(shown.code == 0, qPrintable(shown.err));
    QVERIFY2(shown.out.contains("subject   /CN=operator"), qPrintable(shown.out));
    QVERIFY2(shown.out.contains("issuer    /CN=Fleet CA"), qPrintable(shown.out));
    QVERIFY2(shown.out.contains("certificate authority"), qPrintable(shown.out));
    QVERIFY2(shown.out.contains("(valid)"), qPrintable(shown.out));

    // Issued with no days left: expired within a second.
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"tls", "show", path("fleet/former.pem")}).code == 1, 5000);
    QVERIFY(runRtctl({"tls", "show", path("fleet/former.pem")}).out.contains("EXPIRED"));

    // The key files keep their secrets from other users.
    QCOMPARE(QFile::permissions(path("fleet/ca.key")) & (QFile::ReadOther | QFile::ReadGroup), QFile::Permissions());
    QCOMPARE(QFile::permissions(path("fleet/operator.pem")) & (QFile::ReadOther | QFile::ReadGroup),
             QFile::Permissions());

    const RtctlResult again = runRtctl({"tls", "init", path("fleet")});
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains("there is a certificate authority already"), qPrintable(again.err));
    const RtctlResult badName = runRtctl({"tls", "issue", path("fleet"), "../escape"});
    QCOMPARE(badName.code, 1);
    QVERIFY2(badName.err.contains("cannot name a certificate"), qPrintable(badName.err));
}

void TestTls::badCertificateFilesAreNamed()
{
    // Refused before any connection is tried, naming the file and what is wrong with it.
    const RtctlResult missing = rtctl({"ls", "/" + m_live.namingServer()}, path("fleet/none.pem"));
    QCOMPARE(missing.code, 2);
    QVERIFY2(missing.err.contains(path("fleet/none.pem") + ": cannot be read"), qPrintable(missing.err));
    const RtctlResult foreign
        = rtctl({"ls", "/" + m_live.namingServer()}, path("fleet/ca.pem"), path("other/intruder.pem"));
    QCOMPARE(foreign.code, 2);
    QVERIFY2(foreign.err.contains("does not verify against"), qPrintable(foreign.err));
    const RtctlResult expired
        = rtctl({"ls", "/" + m_live.namingServer()}, path("fleet/ca.pem"), path("fleet/former.pem"));
    QCOMPARE(expired.code, 2);
    QVERIFY2(expired.err.contains("certificate has expired"), qPrintable(expired.err));
    const RtctlResult notAKey = rtctl({"ls", "/" + m_live.namingServer()}, path("fleet/ca.pem"), path("fleet/ca.pem"));
    QCOMPARE(notAKey.code, 2);
    QVERIFY2(notAKey.err.contains("no private key"), qPrintable(notAKey.err));
}

void TestTls::systemRunsOverTls()
{
    const QString server = QLatin1Char('/') + m_live.namingServer();
    const QString managerPath = server + QLatin1Char('/') + hostName() + QStringLiteral(".host_cxt/manager.mgr");
    QTRY_VERIFY_WITH_TIMEOUT(operatorRtctl({"ls", "-R", server}).out.contains("manager.mgr"), 10000);

    // Components in two slaves: the master starts them with its TLS settings.
    for (const char *type : {"ConsoleIn?manager_name=slaveA", "ConsoleOut?manager_name=slaveB"}) {
        const RtctlResult created = operatorRtctl({"mgr", managerPath, "create", type});
        QVERIFY2(created.code == 0, qPrintable(created.err + masterOutput()));
    }
    const QString context = server + QLatin1Char('/') + hostName() + QStringLiteral(".host_cxt/");
    const QString source = context + QStringLiteral("ConsoleIn0.rtc");
    const QString sink = context + QStringLiteral("ConsoleOut0.rtc");
    QTRY_VERIFY_WITH_TIMEOUT(operatorRtctl({"ls", context}).out.contains("ConsoleOut0.rtc"), 10000);
    RtctlResult r = operatorRtctl({"con", source + ":out", sink + ":in"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = operatorRtctl({"act", sink, source});
    QVERIFY2(r.code == 0, qPrintable(r.err));

    // Data from one slave to the other, and to rtctl, which serves its own port over TLS.
    const QString sinkReference = QStringLiteral("corbaname:ssliop:%1#%2.host_cxt/ConsoleOut0.rtc")
                                .arg(m_live.namingServer(), hostName());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::componentStatus(m_orb, sinkReference, "received_count").toLong() > 5, 10000);
    r = operatorRtctl({"print", "-n", "3", source + ":out"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.lines().size(), 3);
    r = operatorRtctl({"deact", source});
    QVERIFY2(r.code == 0, qPrintable(r.err));
}

void TestTls::savesAndRestoresOverTls()
{
    // The deployment engine over TLS: save the live system, lose a component, restore and start it.
    const QString server = QLatin1Char('/') + m_live.namingServer();
    const QString context = server + QLatin1Char('/') + hostName() + QStringLiteral(".host_cxt");
    const QString file = path("system.xml");
    RtctlResult r = operatorRtctl({"cryo", "-n", "TlsSystem", "-o", file, context});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = operatorRtctl({"mgr", context + "/manager.mgr", "delete", "ConsoleOut0"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QTRY_VERIFY_WITH_TIMEOUT(!operatorRtctl({"ls", context}).out.contains("ConsoleOut0.rtc"), 10000);
    r = operatorRtctl({"resurrect", "--create", "-s", m_live.namingServer(), "-m", context + "/manager.mgr", file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = operatorRtctl({"start", "-s", m_live.namingServer(), file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    r = operatorRtctl({"diff", "-s", m_live.namingServer(), file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    const QString sinkReference = QStringLiteral("corbaname:ssliop:%1#%2.host_cxt/ConsoleOut0.rtc")
                                      .arg(m_live.namingServer(), hostName());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::componentStatus(m_orb, sinkReference, "received_count").toLong() > 5, 10000);
    r = operatorRtctl({"stop", "-s", m_live.namingServer(), file});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
}

void TestTls::refusedPeers_data()
{
    QTest::addColumn<QString>("certificate");
    QTest::addColumn<QString>("serverSays");
    QTest::newRow("no certificate") << QString() << "certificate required";
    QTest::newRow("another authority") << "other/intruder.pem" << "unable to get local issuer certificate";
    QTest::newRow("expired") << "fleet/former.pem" << "certificate has expired";
}

void TestTls::refusedPeers()
{
    QFETCH(QString, certificate);
    QFETCH(QString, serverSays);
    // A TLS client of its own (OpenSSL's), since rtctl checks its files before it connects: the
    // master refuses during the handshake, before a single request, and says why in its log.
    QStringList arguments {QStringLiteral("s_client"), QStringLiteral("-connect"),
                           QStringLiteral("127.0.0.1:%1").arg(m_masterPort), QStringLiteral("-CAfile"),
                           path("fleet/ca.pem")};
    if (!certificate.isEmpty())
        arguments << QStringLiteral("-cert") << path(certificate) << QStringLiteral("-key") << path(certificate);
    const qsizetype before = masterOutput().size();
    QProcess client;
    client.setProcessChannelMode(QProcess::MergedChannels);
    client.start(QStringLiteral("openssl"), arguments);
    client.closeWriteChannel();
    QVERIFY(LiveTest::waitForExit(&client, 20000));
    const auto logged = [&] { return masterOutput().mid(before); };
    QTRY_VERIFY2_WITH_TIMEOUT(logged().contains("TLS: refused the connection of 127.0.0.1:") && logged().contains(serverSays),
                              qPrintable(logged() + QString::fromLocal8Bit(client.readAll())), 5000);
}

void TestTls::plainClientGetsNoService()
{
    // No TLS at all: the servers accept no plain connection.
    const RtctlResult plain = runRtctl({"ls", "/" + m_live.namingServer()},
                                       {{"XDG_RUNTIME_DIR", m_dir.filePath(QStringLiteral("runtime"))}});
    QCOMPARE(plain.code, 1);
    QVERIFY2(plain.err.contains("connection failed") || plain.err.contains("unreachable"), qPrintable(plain.err));
    // With the authority but no certificate of its own, the name server refuses the handshake.
    const RtctlResult anonymous = rtctl({"ls", "/" + m_live.namingServer()}, path("fleet/ca.pem"));
    QCOMPARE(anonymous.code, 1);
    QVERIFY2(anonymous.err.contains("certificate required") || anonymous.err.contains("presents no certificate"),
             qPrintable(anonymous.err));
}

void TestTls::connectionLimitCountsTlsConnections()
{
    // corba.max_connections bounds TLS connections as it bounds TCP ones.
    const quint16 port = LiveTest::freePort();
    QString error;
    QProcess *manager = startTlsManager(port, {"corba.max_connections=2", "naming.enable=NO"}, &error);
    QVERIFY2(manager, qPrintable(error));
    std::vector<std::unique_ptr<QProcess>> clients;
    QByteArray said;
    for (int i = 0; i < 4 && !said.contains("as many as corba.max_connections allows"); ++i) {
        auto client = std::make_unique<QProcess>();
        client->setProcessChannelMode(QProcess::MergedChannels);
        // Stays connected while its input is open.
        client->start(QStringLiteral("openssl"),
                      {"s_client", "-connect", QStringLiteral("127.0.0.1:%1").arg(port), "-CAfile", path("fleet/ca.pem"),
                       "-cert", path("fleet/operator.pem"), "-key", path("fleet/operator.pem")});
        QVERIFY(client->waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(client->peek(1 << 16).contains("CONNECTED") || client->state() != QProcess::Running,
                                 10000);
        clients.push_back(std::move(client));
        QTest::qWait(0);
        manager->waitForReadyRead(500);
        said += manager->readAll();
    }
    QTRY_VERIFY2_WITH_TIMEOUT((said += manager->readAll()).contains("as many as corba.max_connections allows"),
                              said.constData(), 10000);
    QVERIFY2(said.contains("refused a connection from giop:ssl:127.0.0.1:"), said.constData());
    for (auto &client : clients)
        client->kill();
    for (auto &client : clients)
        client->waitForFinished();
    m_live.stop(manager);
}

void TestTls::dataFlowsBetweenTwoHosts()
{
    // Two hosts of their own (network namespaces), each with a TLS name server and manager.
    LiveTest::SimulatedHosts hosts;
    QString why;
    if (!hosts.create({"tlsA", "tlsB"}, &why))
        QSKIP(qPrintable(QStringLiteral("cannot simulate hosts: ") + why));
    std::map<QString, std::unique_ptr<LiveTest::LiveSystem>> live;
    for (const QString host : {"tlsA", "tlsB"}) {
        live[host] = std::make_unique<LiveTest::LiveSystem>(hosts.liveHost(host));
        QString error;
        QVERIFY2(live[host]->startTlsNameServer(path("fleet/ca.pem"), path("fleet/node.pem"), &error),
                 qPrintable(error));
        QVERIFY2(live[host]->startHostManager(RTMANAGER_PATH, 2810, host,
                                              {"corba.ssl.certificate_authority_file=" + path("fleet/ca.pem"),
                                               "corba.ssl.key_file=" + path("fleet/node.pem")},
                                              &error),
                 qPrintable(error));
    }
    const auto context = [&](const QString &host) {
        return QStringLiteral("/%1/%2.host_cxt/").arg(live[host]->namingServer(), host);
    };
    RtctlResult r = operatorRtctl({"mgr", context("tlsA") + "manager.mgr", "create", "ConsoleIn"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = operatorRtctl({"mgr", context("tlsB") + "manager.mgr", "create", "ConsoleOut"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QString source = context("tlsA") + "ConsoleIn0.rtc";
    const QString sink = context("tlsB") + "ConsoleOut0.rtc";
    r = operatorRtctl({"con", source + ":out", sink + ":in"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = operatorRtctl({"act", sink, source});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QString sinkReference
        = QStringLiteral("corbaname:ssliop:%1#tlsB.host_cxt/ConsoleOut0.rtc").arg(live["tlsB"]->namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::componentStatus(m_orb, sinkReference, "received_count").toLong() > 5, 10000);
    r = operatorRtctl({"deact", source});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    live.clear();
    hosts.remove();
}

void TestTls::localRuntimeWithTls()
{
    const QHash<QString, QString> environment {{"XDG_RUNTIME_DIR", m_dir.filePath(QStringLiteral("runtime"))}};
    const RtctlResult started = runRtctl({"local", "start", "--tls", "--json"}, environment);
    QVERIFY2(started.code == 0, qPrintable(started.err));
    const QJsonObject state = started.json().object();
    QVERIFY(state["tls"].toBool());
    const QString server = QStringLiteral("/127.0.0.1:%1").arg(state["nameServer"].toObject()["port"].toInt());

    // rtctl finds the runtime's certificates by itself.
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"ls", "-R", server}, environment).out.contains("manager.mgr"), 10000);
    const RtctlResult shown = runRtctl({"tls", "show"}, environment);
    QVERIFY2(shown.code == 0 && shown.out.contains("TLS of the local runtime"), qPrintable(shown.out + shown.err));
    const RtctlResult status = runRtctl({"local", "status"}, environment);
    QVERIFY2(status.out.contains("TLS         on"), qPrintable(status.out));

    // Without the user's certificate the runtime refuses.
    QHash<QString, QString> anonymous = environment;
    anonymous.insert("RTSTUDIO_TLS_CA", state["folder"].toString() + "/tls/ca.pem");
    const RtctlResult refused = runRtctl({"ls", server}, anonymous);
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains("certificate required") || refused.err.contains("presents no certificate"),
             qPrintable(refused.err));

    // A runtime whose manager died leaves its state file behind: rtctl no longer takes its TLS.
    ::kill(pid_t(state["manager"].toObject()["pid"].toInteger()), SIGKILL);
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"tls", "show"}, environment).out.startsWith("TLS off"), 10000);

    // Started again without --tls, the runtime is plain again.
    const RtctlResult plain = runRtctl({"local", "start", "--json"}, environment);
    QVERIFY2(plain.code == 0, qPrintable(plain.err));
    QVERIFY(!plain.json().object()["tls"].toBool());
    const QString plainServer
        = QStringLiteral("/127.0.0.1:%1").arg(plain.json().object()["nameServer"].toObject()["port"].toInt());
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"ls", "-R", plainServer}, environment).out.contains("manager.mgr"), 10000);
    QCOMPARE(runRtctl({"local", "stop"}, environment).code, 0);
}

void TestTls::openRtmTlsConfigurationServes()
{
    // The lines OpenRTM-aist's TLS sample puts in rtc.conf, so that one file serves both: its TLS
    // module preloaded, the name server as a corbaloc:ssliop URL, quoted transport rules.
    QString error;
    QProcess *manager = startTlsManager(
        LiveTest::freePort(),
        {QStringLiteral("corba.nameservers=corbaloc:ssliop:127.0.0.1:%1").arg(m_live.namingPort()),
         QStringLiteral("naming.formats=shared.host_cxt/%n.rtc"), QStringLiteral("manager.naming_formats=shared.host_cxt/%n.mgr"),
         QStringLiteral("manager.preload.modules=SSLTransport.so"),
         QStringLiteral("corba.args=-ORBserverTransportRule \"* ssl\" -ORBclientTransportRule \"* ssl\""),
         QStringLiteral("manager.components.precreate=ConsoleOut")},
        &error);
    QVERIFY2(manager, qPrintable(error));
    const QString started = QString::fromLocal8Bit(m_live.printedWhileStarting(manager));
    QVERIFY2(started.contains("SSLTransport.so (OpenRTM-aist's TLS module) is not loaded: TLS is on"), qPrintable(started));
    QVERIFY2(!started.contains("load_module"), qPrintable(started));
    const QString context = "/" + m_live.namingServer() + "/shared.host_cxt";
    QTRY_VERIFY_WITH_TIMEOUT(operatorRtctl({"ls", context}).out.contains("ConsoleOut0.rtc"), 10000);
    QCOMPARE(operatorRtctl({"act", context + "/ConsoleOut0.rtc"}).code, 0);
    m_live.stop(manager);
}

void TestTls::pythonComponentOverTls()
{
#ifndef RTSTUDIO_PYTHON_PATH
    QSKIP("the Python runtime is not built (pybind11-dev, python3-dev)");
#else
    // A Python component with the node's certificate in its rtc.conf, between two components of the
    // TLS master: samples go in, are multiplied by 1000 in Python, and come out over TLS.
    QFile conf(path("pyscaler.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly | QIODevice::Text));
    // Its manager named apart from the master's, which it would replace in the name server.
    conf.write(QStringLiteral("corba.nameservers: %1\nnaming.formats: pytls.host_cxt/%n.rtc\nlogger.enable: NO\n"
                              "manager.naming_formats: pytls.host_cxt/%n.mgr\n"
                              "corba.ssl.certificate_authority_file: %2\ncorba.ssl.key_file: %3\n")
                   .arg(m_live.namingServer(), path("fleet/ca.pem"), path("fleet/node.pem"))
                   .toUtf8());
    conf.close();
    const QString server = QLatin1Char('/') + m_live.namingServer();
    QString error;
    QProcess *python = m_live.startRegistered(
        QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE),
        {RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python/PyScaler.py"), QStringLiteral("-f"), conf.fileName()},
        [&] { return operatorRtctl({"ls", server + "/pytls.host_cxt"}).out.contains("PyScaler0.rtc"); }, &error, 20000,
        LiveTest::pythonEnvironment(RTSTUDIO_PYTHON_PATH, QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD)));
    QVERIFY2(python, qPrintable(error));

    const QString managerPath = server + QLatin1Char('/') + hostName() + QStringLiteral(".host_cxt/manager.mgr");
    const RtctlResult created = operatorRtctl(
        {"mgr", managerPath, "create", "ConsoleIn?instance_name=PyTlsSource&manager_name=pyslave", "create",
         "ConsoleOut?instance_name=PyTlsSink&manager_name=pyslave"});
    QVERIFY2(created.code == 0, qPrintable(created.err + masterOutput()));
    const QString context = server + QLatin1Char('/') + hostName() + QStringLiteral(".host_cxt/");
    const QString scaler = server + QStringLiteral("/pytls.host_cxt/PyScaler0.rtc");
    QTRY_VERIFY_WITH_TIMEOUT(operatorRtctl({"ls", context}).out.contains("PyTlsSink.rtc"), 10000);
    for (const QStringList &ports : {QStringList {context + "PyTlsSource.rtc:out", scaler + ":in"},
                                     QStringList {scaler + ":out", context + "PyTlsSink.rtc:in"}}) {
        const RtctlResult connected = operatorRtctl(QStringList {"con"} + ports);
        QVERIFY2(connected.code == 0, qPrintable(connected.err));
    }
    const RtctlResult activated = operatorRtctl({"act", context + "PyTlsSink.rtc", scaler, context + "PyTlsSource.rtc"});
    QVERIFY2(activated.code == 0, qPrintable(activated.err));
    const QString sink = QStringLiteral("corbaname:ssliop:%1#%2.host_cxt/PyTlsSink.rtc").arg(m_live.namingServer(), hostName());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::componentStatus(m_orb, sink, "received_count").toLong() >= 3, 15000);
    const QList<qint64> values = LiveTest::integers(LiveTest::componentStatus(m_orb, sink, "received_values"));
    QVERIFY(!values.isEmpty());
    for (const qint64 value : values)
        QVERIFY2(value != 0 && value % 1000 == 0, qPrintable(QString::number(value)));
    const RtctlResult deactivated = operatorRtctl({"deact", context + "PyTlsSource.rtc"});
    QVERIFY2(deactivated.code == 0, qPrintable(deactivated.err));
    m_live.stop(python);
#endif
}

QTEST_GUILESS_MAIN(TestTls)
#include "tst_tls.moc"
