// SPDX-License-Identifier: MIT
// From design to a running component: a profile with data ports, provided and required service
// ports of a user IDL and scalar and vector configuration is generated with `rtctl gen`, user code
// goes into onExecute and the servant, a regeneration merges around it, CMake builds the project
// against the component SDK of this build tree, rtmanager loads the module, and the instances
// exchange data with built-in components, call each other's service and follow configuration
// changes. The standalone <Name>Comp registers in the name server and is activated with rtctl.
#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkgreeteredits.h"
#include "sdkproject.h"

#include <QtTest>

#include <functional>

namespace {

const QString fixtureDir = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter");

} // namespace

class TestSdkGenerated : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void userCodeSurvivesRegeneration();
    void moduleRunsInManager();
    void standaloneComponentIsDrivenByRtctl();

private:
    RtctlResult rtctl(const QStringList &arguments);
    QString host() const { return QStringLiteral("/%1/sdkhost.host_cxt").arg(m_live.namingServer()); }
    QString iorOf(const QString &path);
    QString lastValue(const QString &path);

    QTemporaryDir m_work;
    QString m_project;
    QString m_buildLog;
    LiveTest::LiveSystem m_live;
    CORBA::ORB_var m_orb;
};

RtctlResult TestSdkGenerated::rtctl(const QStringList &arguments)
{
    return runRtctlAt(host(), arguments);
}

void TestSdkGenerated::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QVERIFY(m_work.isValid());
    m_project = m_work.filePath("SdkGreeter");
    const QStringList generate{"gen", fixtureDir + "/RTC.xml", "--lang", "cpp", "-o", m_project, "--idl-dir", fixtureDir};
    RtctlResult generated = runRtctl(generate);
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QVERIFY2(QFile::exists(m_project + "/include/SdkGreeter/VectorConvert.h"),
             "a vector parameter brings the vector conversion header");
    QString error;
    for (const SdkTest::UserEdit &edit : SdkGreeter::userEdits)
        QVERIFY2(SdkTest::applyEdit(m_project, edit, &error), qPrintable(error));
    // Regenerating merges the profile's blocks around the user's code.
    RtctlResult merged = runRtctl(generate + QStringList{"--merge"});
    QVERIFY2(merged.code == 0, qPrintable(merged.out + merged.err));

    QVERIFY2(SdkTest::buildProject(m_project, RTSTUDIO_BUILD_DIR, &m_buildLog), qPrintable(m_buildLog));
    QVERIFY(QFile::exists(m_project + "/build/src/SdkGreeter.so"));
    QVERIFY(QFile::exists(m_project + "/build/src/SdkGreeterComp"));

    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const QStringList options{"corba.nameservers=" + m_live.namingServer(),
                              "naming.formats=sdkhost.host_cxt/%n.rtc",
                              "manager.naming_formats=sdkhost.host_cxt/%n.mgr",
                              "manager.modules.load_path=" + m_project + "/build/src",
                              "manager.components.precreate=ConsoleIn?exec_cxt.periodic.rate=50,"
                              "ConsoleOut?instance_name=Scaled,ConsoleOut?instance_name=Greetings"};
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, LiveTest::freePort(), options, &error), qPrintable(error));
}

void TestSdkGenerated::cleanupTestCase()
{
    m_live.stopAll();
}

void TestSdkGenerated::userCodeSurvivesRegeneration()
{
    QFile source(m_project + "/src/SdkGreeter.cpp");
    QVERIFY(source.open(QIODevice::ReadOnly));
    const QByteArray text = source.readAll();
    QVERIFY(text.contains("// user code: greet the peer"));
    QVERIFY(text.contains("<rtc-template block=\"bind_config\">"));
    QFile servant(m_project + "/src/GreeterSVC_impl.cpp");
    QVERIFY(servant.open(QIODevice::ReadOnly));
    QVERIFY(servant.readAll().contains("std::string(\"hello \") + name"));
}

QString TestSdkGenerated::iorOf(const QString &path)
{
    // The name server resolves the component's name for us.
    return QStringLiteral("corbaname::%1#sdkhost.host_cxt/%2").arg(m_live.namingServer(), path);
}

QString TestSdkGenerated::lastValue(const QString &path)
{
    static QHash<QString, QString> iors;
    if (!iors.contains(path))
        iors.insert(path, iorOf(path));
    return LiveTest::componentStatus(m_orb, iors.value(path), "last_value");
}

void TestSdkGenerated::moduleRunsInManager()
{
    const QString manager = host() + "/manager.mgr";
    // --timeout is a setting, not an action (it was once taken for a delete).
    RtctlResult r = rtctl({"mgr", "--timeout", "20000", manager, "load", "SdkGreeter", "create", "SdkGreeter?instance_name=Front",
                           "create", "SdkGreeter?instance_name=Back"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    for (const QStringList &link : {QStringList{"ConsoleIn0.rtc:out", "Front.rtc:in"},
                                    QStringList{"Front.rtc:out", "Scaled.rtc:in"},
                                    QStringList{"Front.rtc:peer", "Back.rtc:greet"},
                                    QStringList{"Back.rtc:out", "Greetings.rtc:in"}}) {
        r = rtctl(QStringList{"con"} + link);
        QVERIFY2(r.code == 0, qPrintable(link.join(' ') + ": " + r.out + r.err));
    }
    r = rtctl({"act", "ConsoleIn0.rtc", "Front.rtc", "Back.rtc", "Scaled.rtc", "Greetings.rtc"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));

    // Data in and out: ConsoleIn's counter doubled (gain 2) reaches the sink.
    QTRY_VERIFY_WITH_TIMEOUT(lastValue("Scaled.rtc").toLong() > 0 && lastValue("Scaled.rtc").toLong() % 2 == 0, 20000);
    // The required interface reached the other instance's servant: it reports its greetings.
    QTRY_VERIFY_WITH_TIMEOUT(lastValue("Greetings.rtc").toLong() < 0, 20000);

    // Configuration reaches the bound variables: a new gain, then vector limits.
    r = rtctl({"conf", "Front.rtc", "set", "gain", "3"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(lastValue("Scaled.rtc").toLong() > 0 && lastValue("Scaled.rtc").toLong() % 3 == 0, 20000);
    r = rtctl({"conf", "Front.rtc", "set", "limits", "0,7"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_COMPARE_WITH_TIMEOUT(lastValue("Scaled.rtc"), QString("7"), 20000);
}

void TestSdkGenerated::standaloneComponentIsDrivenByRtctl()
{
    QString error;
    QProcess *comp = m_live.startProcess(m_project + "/build/src/SdkGreeterComp",
                                         {"-f", m_project + "/rtc.conf", "-o",
                                          "corba.nameservers:" + m_live.namingServer(), "-o",
                                          "naming.formats:standalone.host_cxt/%n.rtc", "-o", "corba.master_manager:"},
                                         QString(), &error, 0);
    QVERIFY2(comp != nullptr, qPrintable(error));
    const QString path = QStringLiteral("/%1/standalone.host_cxt/SdkGreeter0.rtc").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", path}).code == 0, 20000);
    RtctlResult r = runRtctl({"act", path});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QTRY_VERIFY_WITH_TIMEOUT(runRtctl({"cat", path}).out.contains("Active"), 10000);
}

QTEST_GUILESS_MAIN(TestSdkGenerated)
#include "tst_sdkgenerated.moc"
