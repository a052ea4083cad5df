// SPDX-License-Identifier: MIT
// rtctl package: a component generated with `rtctl gen` and built against this build tree's SDK
// becomes a Debian package made by dpkg-deb, read back with dpkg-deb (fields, files), its Depends
// from dpkg-shlibdeps; a Python component gives an Architecture: all package; projects without a
// profile, not built, or with a name or version Debian cannot take are refused with the file named.
// Unpacked as dpkg would install it, the package's module is found by rtmanager by its name.
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"

#include <QCryptographicHash>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {

const QString fixtures = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/packages/");
const QString greeterFixture = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter");

QString tool(const QString &program, const QStringList &arguments)
{
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(60000) || process.exitCode() != 0)
        return QString();
    return QString::fromUtf8(process.readAllStandardOutput());
}

QString field(const QString &deb, const QString &name)
{
    return tool(QStringLiteral("dpkg-deb"), {QStringLiteral("-f"), deb, name}).trimmed();
}

/// The paths dpkg-deb -c lists, without the leading '.'.
QStringList contents(const QString &deb)
{
    QStringList paths;
    for (const QString &line : tool(QStringLiteral("dpkg-deb"), {QStringLiteral("-c"), deb})
                                   .split('\n', Qt::SkipEmptyParts))
        paths << line.section(' ', -1).mid(1);
    return paths;
}

QByteArray sha256(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly)
        ? QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256).toHex()
        : QByteArray();
}

} // namespace

class TestComponentPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void controlFields();
    void files();
    void dependsOnLinkedLibraries();
    void dependsGiven();
    void aptWouldInstall();
    void managerFindsInstalledModule();
    void pythonComponent();
    void refused_data();
    void refused();

private:
    RtctlResult package(const QStringList &arguments)
    {
        return runRtctl(QStringList {"package"} + arguments);
    }

    QTemporaryDir m_work;
    QString m_project;
    QString m_arch;
    QString m_multiarch;
    QString m_deb;
    RtctlResult m_packaged;
};

void TestComponentPackage::initTestCase()
{
    QVERIFY(m_work.isValid());
    m_arch = tool("dpkg", {"--print-architecture"}).trimmed();
    m_multiarch = tool("dpkg-architecture", {"-qDEB_HOST_MULTIARCH"}).trimmed();
    QVERIFY(!m_arch.isEmpty() && !m_multiarch.isEmpty());
    // A component with a provided service of its own IDL, generated and built as a user would.
    m_project = m_work.filePath("SdkGreeter");
    const RtctlResult generated = runRtctl({"gen", greeterFixture + "/RTC.xml", "--lang", "cpp",
                                            "-o", m_project, "--idl-dir", greeterFixture});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QString log;
    QVERIFY2(SdkTest::buildProject(m_project, RTSTUDIO_BUILD_DIR, &log), qPrintable(log));
    m_packaged = package({m_project, "-o", m_work.filePath("out")});
    QVERIFY2(m_packaged.code == 0, qPrintable(m_packaged.out + m_packaged.err));
    m_deb = m_packaged.lines().value(0);
    QCOMPARE(m_deb,
             m_work.filePath("out/rtc-rtstudiotests-test-sdkgreeter_1.0.0_" + m_arch + ".deb"));
    QVERIFY(QFile::exists(m_deb));
}

void TestComponentPackage::controlFields()
{
    QCOMPARE(field(m_deb, "Package"), QStringLiteral("rtc-rtstudiotests-test-sdkgreeter"));
    QCOMPARE(field(m_deb, "Version"), QStringLiteral("1.0.0"));
    QCOMPARE(field(m_deb, "Architecture"), m_arch);
    QVERIFY2(field(m_deb, "Maintainer").contains(QRegularExpression("^.+ <.+@.+>$")),
             qPrintable(field(m_deb, "Maintainer")));
    QVERIFY(!field(m_deb, "Description").isEmpty());
    QCOMPARE(field(m_deb, "X-RTC-Types"), QStringLiteral("SdkGreeter"));
    QCOMPARE(field(m_deb, "X-RTC-Profile-Id"),
             QStringLiteral("RTC:RTStudioTests:Test:SdkGreeter:1.0.0"));
    QCOMPARE(field(m_deb, "X-RTC-Profile-SHA256").toLatin1(), sha256(m_project + "/RTC.xml"));
    // The SDK ABI is the SONAME of the SDK library this build tree made.
    const QString sdk = tool("objdump", {"-p", RTSTUDIO_BUILD_DIR + QStringLiteral("/lib/librtstudio_rtm.so")});
    const QRegularExpressionMatch soname = QRegularExpression("SONAME\\s+(\\S+)").match(sdk);
    QVERIFY(soname.hasMatch());
    QCOMPARE(field(m_deb, "X-RTStudio-SDK-ABI"), soname.captured(1));
    // What the command printed is what the package holds.
    QVERIFY(m_packaged.out.contains("X-RTC-Types: SdkGreeter"));
}

void TestComponentPackage::files()
{
    const QString lib
        = "/usr/lib/" + m_multiarch + "/rtstudio/components/rtc-rtstudiotests-test-sdkgreeter/";
    const QString share = "/usr/share/rtstudio/components/rtc-rtstudiotests-test-sdkgreeter/";
    const QStringList paths = contents(m_deb);
    for (const QString &expected :
         {lib + "SdkGreeter.so", lib + "SdkGreeterComp", share + "RTC.xml",
          share + "SdkGreeter.conf", share + "rtc.conf", share + "idl/Greeter.idl"})
        QVERIFY2(paths.contains(expected), qPrintable(expected + " not in\n" + paths.join('\n')));
    // Nothing of the build folder or the sources besides.
    for (const QString &path : paths)
        QVERIFY2(path.endsWith('/') || path.startsWith(lib) || path.startsWith(share),
                 qPrintable(path));
}

void TestComponentPackage::dependsOnLinkedLibraries()
{
    const QStringList depends = field(m_deb, "Depends").split(", ");
    // dpkg-shlibdeps's names of the Debian libraries the component links.
    for (const QString &library :
         {QStringLiteral("libstdc++6"), QStringLiteral("libc6"), QStringLiteral("libomniorb4")}) {
        const bool found
            = std::any_of(depends.cbegin(), depends.cend(),
                          [&library](const QString &d) { return d.startsWith(library); });
        QVERIFY2(found, qPrintable(library + " not in " + depends.join(", ")));
    }
    // The SDK library of the build tree comes from no package: left out, with a warning naming it.
    for (const QString &d : depends)
        QVERIFY2(!d.contains("rtstudio"), qPrintable(d));
    QVERIFY2(m_packaged.err.contains(QRegularExpression(
                 "warning: librtstudio_rtm\\.so\\.\\d+ comes from no Debian package")),
             qPrintable(m_packaged.err));
}

void TestComponentPackage::dependsGiven()
{
    const RtctlResult r = package({m_project, "-o", m_work.filePath("given.deb"), "--depends",
                                   "rtc-rtstudiotests-test-other (>= 2.0)", "--maintainer",
                                   "Robot Team <team@example.org>"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QString deb = m_work.filePath("given.deb");
    QVERIFY(field(deb, "Depends").endsWith(", rtc-rtstudiotests-test-other (>= 2.0)"));
    QCOMPARE(field(deb, "Maintainer"), QStringLiteral("Robot Team <team@example.org>"));
}

void TestComponentPackage::aptWouldInstall()
{
    // apt takes the file as `apt install ./file.deb` does, its dependencies met on this machine.
    QProcess apt;
    apt.setProcessChannelMode(QProcess::MergedChannels);
    apt.start("apt-get", {"install", "--simulate", "-o", "Debug::NoLocking=1", m_deb});
    QVERIFY(apt.waitForFinished(120000));
    const QString output = QString::fromUtf8(apt.readAll());
    QVERIFY2(apt.exitCode() == 0, qPrintable(output));
    QVERIFY2(output.contains("Inst rtc-rtstudiotests-test-sdkgreeter (1.0.0"), qPrintable(output));
}

void TestComponentPackage::managerFindsInstalledModule()
{
    // The package's files below a root folder, as dpkg would install them below /.
    const QString root = m_work.filePath("installed");
    tool("dpkg-deb", {"-x", m_deb, root});
    const QString packages = root + "/usr/lib/" + m_multiarch + "/rtstudio/components";
    QVERIFY(QFile::exists(packages + "/rtc-rtstudiotests-test-sdkgreeter/SdkGreeter.so"));
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(live.startManager(RTMANAGER_PATH, port,
                               {"naming.enable=NO",
                                "manager.modules.load_path=" + m_work.filePath("none"),
                                "manager.modules.package_path=" + packages},
                               &error),
             qPrintable(error));
    const QString manager = QStringLiteral("corbaloc::%1:%2").arg(live.address()).arg(port);
    // Loaded by name from its package's folder, and its type created.
    const RtctlResult r = runRtctl({"mgr", manager, "load", "SdkGreeter", "create", "SdkGreeter"});
    QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
    QVERIFY2(r.out.startsWith("SdkGreeter"), qPrintable(r.out));
    const RtctlResult listed = runRtctl({"mgr", manager, "list"});
    QVERIFY2(listed.out.contains(packages + "/rtc-rtstudiotests-test-sdkgreeter/SdkGreeter.so"),
             qPrintable(listed.out));
    live.stopAll();
}

void TestComponentPackage::pythonComponent()
{
    const RtctlResult r = package({fixtures + "pycomp", "-o", m_work.filePath("py")});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const QString deb = r.lines().value(0);
    QCOMPARE(QFileInfo(deb).fileName(),
             QStringLiteral("rtc-rtstudiotests-packaging-pygreeter_1.2_all.deb"));
    QCOMPARE(field(deb, "Architecture"), QStringLiteral("all"));
    QCOMPARE(field(deb, "Version"), QStringLiteral("1.2")); // the profile's "v1_2"
    // A library of the profile that is a package name is a dependency; others are named in a
    // warning.
    QCOMPARE(field(deb, "Depends"), QStringLiteral("rtc-rtstudio-example-consolein (>= 1.0.0)"));
    QVERIFY2(r.err.contains("'NumPy'"), qPrintable(r.err));
    QVERIFY(field(deb, "X-RTStudio-SDK-ABI").isEmpty());
    const QString share = "/usr/share/rtstudio/components/rtc-rtstudiotests-packaging-pygreeter/";
    const QStringList paths = contents(deb);
    for (const QString &expected : {share + "PyGreeter.py", share + "PyGreeter.conf",
                                    share + "RTC.xml", share + "idl/Greeting.idl"})
        QVERIFY2(paths.contains(expected), qPrintable(expected + " not in\n" + paths.join('\n')));
}

void TestComponentPackage::refused_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("message"); // parts of the message, in order

    QTest::newRow("no RTC.xml") << QStringList {fixtures + "noprofile"}
                                << QStringList {fixtures + "noprofile/RTC.xml", "no RTC.xml"};
    QTest::newRow("no such folder") << QStringList {fixtures + "missing"}
                                    << QStringList {fixtures + "missing", "no such project folder"};
    QTest::newRow("not built") << QStringList {fixtures + "unbuilt"}
                               << QStringList {fixtures + "unbuilt/build", "not built"};
    QTest::newRow("not built in the folder given")
        << QStringList {m_project, "--build-dir", fixtures + "unbuilt"}
        << QStringList {fixtures + "unbuilt", "not built", "SdkGreeter.so", "SdkGreeterComp"};
    QTest::newRow("invalid version")
        << QStringList {fixtures + "badversion"}
        << QStringList {fixtures + "badversion/RTC.xml", "invalid version", "'beta two'"};
    QTest::newRow("name without letters")
        << QStringList {fixtures + "badname"}
        << QStringList {fixtures + "badname/RTC.xml", "invalid package name", "'__'"};
    QTest::newRow("invalid name given") << QStringList {m_project, "--name", "Greeter_Pkg"}
                                        << QStringList {"invalid package name", "'Greeter_Pkg'"};
}

void TestComponentPackage::refused()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, message);
    QTemporaryDir out;
    const RtctlResult r = package(arguments + QStringList {"-o", out.path()});
    QCOMPARE(r.code, 1);
    qsizetype at = 0;
    for (const QString &part : message) {
        at = r.err.indexOf(part, at);
        QVERIFY2(at >= 0, qPrintable("'" + part + "' not in: " + r.err));
    }
    QVERIFY2(QDir(out.path()).isEmpty(), "nothing written");
}

QTEST_GUILESS_MAIN(TestComponentPackage)
#include "tst_componentpackage.moc"
