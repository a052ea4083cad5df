// SPDX-License-Identifier: MIT
// OpenRTM-aist 2.x built with its SSL transport (SSL_ENABLE) and RT Studio on one certificate
// authority and one rtc.conf: OpenRTM-aist's example programs and an rtmanager register in one TLS
// name server, rtctl drives both with an operator's certificate, data flows between them over TLS
// both ways, and OpenRTM-aist's programs refuse a peer of another authority. Skipped without an
// OpenRTM-aist prefix, or with one built without SSL.

#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "tlsorb.h"

#include <RTC.hh>

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);

/// The ORB options of OpenRTM-aist's TLS sample: TLS only, served on @p port (0: any).
QString tlsOnly(quint16 port)
{
    return QStringLiteral("-ORBserverTransportRule \"* ssl\" -ORBclientTransportRule \"* ssl\" "
                          "-ORBendPoint giop:ssl:127.0.0.1:%1")
        .arg(port ? QString::number(port) : QString());
}

} // namespace

class TestInteropTls : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void bothRegisterOverTls();
    void dataFlowsBothWaysOverTls();
    void rtctlDrivesOpenRtmOverTls();
    void anotherAuthorityIsRefused();

private:
    QString path(const QString &name) const { return m_dir.filePath(name); }
    RtctlResult rtctl(const QStringList &arguments, const QString &key = QStringLiteral("fleet/operator.pem")) const
    {
        return runRtctl(arguments, {{"RTSTUDIO_TLS_CA", path("fleet/ca.pem")}, {"RTSTUDIO_TLS_KEY", path(key)},
                                    {"XDG_RUNTIME_DIR", m_dir.path()}});
    }
    bool writeSharedConf(QString *error) const;
    QProcess *startExample(const QString &name, QString *error, const QStringList &options = {});
    bool initOrb(QString *error);

    QTemporaryDir m_dir {QDir::tempPath() + QStringLiteral("/rtinteroptlsXXXXXX")};
    LiveTest::LiveSystem m_live;
    QString m_openRtm; ///< the name server context of OpenRTM-aist's programs
    QString m_ours;    ///< and of rtmanager's components
    QProcess *m_consoleOut = nullptr;
    quint16 m_consoleOutPort = 0; ///< where OpenRTM-aist's ConsoleOut serves TLS
    CORBA::ORB_var m_orb;
};

bool TestInteropTls::writeSharedConf(QString *error) const
{
    // OpenRTM-aist's TLS sample: its module preloaded, the keys, a name server reached over TLS,
    // TLS only in both directions. rtmanager reads the same file.
    const QStringList lines {
        QStringLiteral("corba.nameservers: corbaloc:ssliop:127.0.0.1:%1").arg(m_live.namingPort()),
        QStringLiteral("corba.endpoints: 127.0.0.1:"),
        QStringLiteral("logger.enable: NO"),
        QStringLiteral("manager.modules.load_path: %1/lib/openrtm-2.1/ssl").arg(openRtmPrefix),
        QStringLiteral("manager.preload.modules: SSLTransport.so"),
        QStringLiteral("corba.ssl.certificate_authority_file: ") + path("fleet/ca.pem"),
        QStringLiteral("corba.ssl.key_file: ") + path("fleet/node.pem"),
        // OpenRTM-aist hands omniORB the key only with a password; an unencrypted key ignores it.
        QStringLiteral("corba.ssl.key_file_password: unused"),
        QStringLiteral("corba.args: ") + tlsOnly(0),
    };
    QFile conf(path("rtc.conf"));
    if (!conf.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = conf.fileName() + QStringLiteral(": ") + conf.errorString();
        return false;
    }
    conf.write((lines.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8());
    return true;
}

QProcess *TestInteropTls::startExample(const QString &name, QString *error, const QStringList &options)
{
    // The shared rtc.conf's TLS name server, rather than the plain address given first.
    return m_live.startOpenRtmExample(
        openRtmPrefix, name, QStringLiteral("openrtm"), error,
        QStringList {QStringLiteral("corba.nameservers:corbaloc:ssliop:127.0.0.1:%1").arg(m_live.namingPort())} + options,
        {QStringLiteral("-f"), path("rtc.conf")});
}

bool TestInteropTls::initOrb(QString *error)
{
    // The test reads the components' status itself, as the operator.
    std::string reason;
    m_orb = LiveTest::initOrb("tst_interoptls",
                              {path("fleet/ca.pem").toStdString(), path("fleet/operator.pem").toStdString(), {}}, &reason);
    *error = QString::fromStdString(reason);
    return !CORBA::is_nil(m_orb);
}

void TestInteropTls::initTestCase()
{
    if (openRtmPrefix.isEmpty())
        QSKIP("skipped: no OpenRTM-aist");
    if (!QFile::exists(openRtmPrefix + QStringLiteral("/lib/openrtm-2.1/ssl/SSLTransport.so")))
        QSKIP(qPrintable(QStringLiteral("skipped: the OpenRTM-aist at %1 was built without SSL_ENABLE "
                                        "(no lib/openrtm-2.1/ssl/SSLTransport.so)")
                             .arg(openRtmPrefix)));
    LiveTest::useOpenRtm(openRtmPrefix);
    QVERIFY(m_dir.isValid());
    const QList<QStringList> steps {
        {"tls", "init", path("fleet"), "--name", "Fleet CA"},
        {"tls", "issue", path("fleet"), "node", "--host", "127.0.0.1"},
        {"tls", "issue", path("fleet"), "operator"},
        {"tls", "init", path("other"), "--name", "Other CA"},
        {"tls", "issue", path("other"), "intruder"},
    };
    QString made;
    QVERIFY2(runRtctlAll(steps, &made), qPrintable(made));
    QString error;
    QVERIFY2(m_live.startTlsNameServer(path("fleet/ca.pem"), path("fleet/node.pem"), &error), qPrintable(error));
    QVERIFY2(writeSharedConf(&error), qPrintable(error));
    QVERIFY2(initOrb(&error), qPrintable(error));
    m_openRtm = QStringLiteral("/%1/openrtm.host_cxt/").arg(m_live.namingServer());
    m_ours = QStringLiteral("/%1/ours.host_cxt/").arg(m_live.namingServer());

    QVERIFY2(startExample(QStringLiteral("SeqOutComp"), &error), qPrintable(error));
    m_consoleOutPort = LiveTest::freePort();
    m_consoleOut = startExample(QStringLiteral("ConsoleOutComp"), &error, {"corba.args:" + tlsOnly(m_consoleOutPort)});
    QVERIFY2(m_consoleOut, qPrintable(error));
    m_live.setErrorsRead(true);
    QVERIFY2(m_live.startProcess(RTMANAGER_PATH,
                                 {"-f", path("rtc.conf"), "-o", "manager.is_master=YES", "-o",
                                  QStringLiteral("corba.master_manager=127.0.0.1:%1").arg(LiveTest::freePort()), "-o",
                                  "naming.formats=ours.host_cxt/%n.rtc", "-o", "manager.naming_formats=ours.host_cxt/%n.mgr",
                                  "-o", "manager.components.precreate=ConsoleIn,ConsoleOut"},
                                 QStringLiteral("rtmanager ready"), &error),
             qPrintable(error));
}

void TestInteropTls::cleanupTestCase()
{
    m_live.stopAll();
    if (!CORBA::is_nil(m_orb))
        m_orb->destroy();
}

void TestInteropTls::bothRegisterOverTls()
{
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls", m_openRtm}).out.contains("SeqOut0.rtc")
                                 && rtctl({"ls", m_openRtm}).out.contains("ConsoleOut0.rtc"),
                             30000);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls", m_ours}).out.contains("ConsoleIn0.rtc"), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"ls", "/" + m_live.namingServer()}).out.contains("manager.mgr")
                                 || rtctl({"ls", m_ours}).out.contains("manager.mgr"),
                             10000);
}

void TestInteropTls::dataFlowsBothWaysOverTls()
{
    // rtmanager's ConsoleIn (a counter) → OpenRTM-aist's ConsoleOut, which prints what it reads.
    RtctlResult r = rtctl({"con", m_ours + "ConsoleIn0.rtc:out", m_openRtm + "ConsoleOut0.rtc:in"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    // OpenRTM-aist's SeqOut → rtmanager's ConsoleOut, which counts what it receives.
    r = rtctl({"con", m_openRtm + "SeqOut0.rtc:Long", m_ours + "ConsoleOut0.rtc:in"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = rtctl({"act", m_ours + "ConsoleIn0.rtc", m_ours + "ConsoleOut0.rtc", m_openRtm + "SeqOut0.rtc",
               m_openRtm + "ConsoleOut0.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.err));

    QByteArray printed;
    QTRY_VERIFY2_WITH_TIMEOUT((printed += m_consoleOut->readAllStandardOutput(), printed.count("Received: ") >= 3),
                              printed.constData(), 15000);
    const QString sink = QStringLiteral("corbaname:ssliop:%1#ours.host_cxt/ConsoleOut0.rtc").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(LiveTest::componentStatus(m_orb, sink, "received_count").toLong() >= 3, 15000);
    r = rtctl({"deact", m_ours + "ConsoleIn0.rtc", m_openRtm + "SeqOut0.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
}

void TestInteropTls::rtctlDrivesOpenRtmOverTls()
{
    // rtctl serves a port of its own over TLS: OpenRTM-aist's SeqOut sends to it, and it writes
    // into OpenRTM-aist's ConsoleOut.
    RtctlResult r = rtctl({"act", m_openRtm + "SeqOut0.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    r = rtctl({"print", "-n", "2", m_openRtm + "SeqOut0.rtc:Long"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.lines().size(), 2);
    r = rtctl({"inject", m_openRtm + "ConsoleOut0.rtc:in", "4242"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QByteArray printed;
    QTRY_VERIFY2_WITH_TIMEOUT((printed += m_consoleOut->readAllStandardOutput(), printed.contains("Received: 4242")),
                              printed.constData(), 10000);
    const RtctlResult state = rtctl({"cat", m_openRtm + "ConsoleOut0.rtc"});
    QVERIFY2(state.code == 0 && state.out.contains("Active"), qPrintable(state.out + state.err));
}

void TestInteropTls::anotherAuthorityIsRefused()
{
    // A certificate of another authority opens nothing: not the name server,
    const RtctlResult listed = runRtctl({"ls", m_openRtm}, {{"RTSTUDIO_TLS_CA", path("other/ca.pem")},
                                                            {"RTSTUDIO_TLS_KEY", path("other/intruder.pem")},
                                                            {"XDG_RUNTIME_DIR", m_dir.path()}});
    QCOMPARE(listed.code, 1);
    QVERIFY2(listed.err.contains("certificate"), qPrintable(listed.err));
    // nor OpenRTM-aist's component, which refuses the handshake (TLS 1.2: during the handshake, where
    // OpenSSL's client says so) while a certificate of the fleet passes.
    for (const auto &[certificate, refused] : {std::pair {"other/intruder.pem", true}, {"fleet/operator.pem", false}}) {
        QProcess client;
        client.setProcessChannelMode(QProcess::MergedChannels);
        client.start(QStringLiteral("openssl"),
                     {"s_client", "-tls1_2", "-connect", QStringLiteral("127.0.0.1:%1").arg(m_consoleOutPort),
                      "-CAfile", path("fleet/ca.pem"), "-cert", path(certificate), "-key", path(certificate)});
        client.closeWriteChannel();
        QVERIFY(LiveTest::waitForExit(&client, 20000));
        const QByteArray said = client.readAll();
        QVERIFY2(said.contains("alert") == refused, said.constData());
        QVERIFY2(said.contains("Verify return code: 0 (ok)"), said.constData()); // the node's certificate, both times
    }
}

QTEST_GUILESS_MAIN(TestInteropTls)
#include "tst_interoptls.moc"
