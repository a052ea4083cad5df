// SPDX-License-Identifier: MIT
// The SDK's IDL as users build on it, against the build tree's prefix: every wrapper header of
// rtm/idl (OpenRTM-aist's set and its camera and manipulator extensions) compiled together as C++11,
// the extension libraries' names linked, rtm-skelwrapper's outputs for OpenRTM-aist's options, and
// projects in each IDL layout (OpenRTP 1.2, OpenRTP 2.0, hand-written with --include-dir, one on the
// extension types) configured, built and run, against the build tree's prefix and against a copy
// installed with cmake --install.
#include "sdkproject.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {

constexpr int configureTimeoutMs = 120 * 1000;
constexpr int buildTimeoutMs = 300 * 1000;
constexpr int toolTimeoutMs = 30 * 1000;

using SdkTest::failure;
using SdkTest::run;
using SdkTest::RunResult;

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

bool writeText(const QString &path, const QByteArray &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
}

// A folder of its own for each data row.
QString rowFolder(const char *kind)
{
    return QStringLiteral("%1-%2").arg(QLatin1String(kind)).arg(qHash(QByteArray(QTest::currentDataTag())));
}

// The four files rtm-skelwrapper writes for Relay.idl, by name.
const QStringList &wrapperFiles()
{
    static const QStringList files{"RelaySkel.h", "RelaySkel.cpp", "RelayStub.h", "RelayStub.cpp"};
    return files;
}

} // namespace

class TestSdkIdlFlow : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void everyWrapperCompilesAsCxx11();
    void extensionSkelIncludesTheCoreSet();
    void extensionLibraryNamesLink_data();
    void extensionLibraryNamesLink();
    void wrapperWritesIntoTheCurrentFolder();
    void wrapperIncludeDir_data();
    void wrapperIncludeDir();
    void wrapperOutputDir_data();
    void wrapperOutputDir();
    void wrapperDependenciesAndUtil();
    void project_data();
    void project();

private:
    QProcessEnvironment environment(const QString &prefix) const;
    QProcessEnvironment environment() const { return environment(m_prefix); }
    QString rtmIdl() const { return m_prefix + QStringLiteral("/include/openrtm-2.1/rtm/idl"); }
    /// Runs rtm-skelwrapper in m_workDir/<folder> (made first); false and a message on failure.
    bool wrap(const QString &folder, const QStringList &arguments, QString *message);
    QStringList cflags() const;

    QTemporaryDir m_workDir{QDir::tempPath() + QStringLiteral("/rtsdkidlXXXXXX")};
    QTemporaryDir m_installDir{QDir::tempPath() + QStringLiteral("/rtsdkidlinstallXXXXXX")};
    QString m_prefix;
    QString m_installPrefix;
};

void TestSdkIdlFlow::initTestCase()
{
    QVERIFY(m_workDir.isValid());
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("python3")).isEmpty(), "python3 is missing");
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("omniidl")).isEmpty(), "omniidl is missing");
    m_prefix = QFileInfo(RTSTUDIO_BUILD_DIR).canonicalFilePath();
    QVERIFY2(QFileInfo::exists(m_prefix + QStringLiteral("/lib/librtstudio_rtm.so")),
             "build the targets rtsdk and rtsdk_stage first");

    // The SDK's own install component, into a folder elsewhere: the projects build against both.
    QVERIFY(m_installDir.isValid());
    m_installPrefix = QFileInfo(m_installDir.path()).canonicalFilePath();
    const RunResult install = run(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                                  {QStringLiteral("--install"), RTSTUDIO_BUILD_DIR,
                                   QStringLiteral("--prefix"), m_installPrefix, QStringLiteral("--component"),
                                   QStringLiteral("sdk")},
                                  QProcessEnvironment::systemEnvironment(), m_workDir.path(), buildTimeoutMs);
    QVERIFY2(install.ok(), qPrintable(failure(QStringLiteral("cmake --install"), install)));
}

// What a user's shell has after adding the prefix: its bin on PATH, nothing from the surrounding build.
QProcessEnvironment TestSdkIdlFlow::environment(const QString &prefix) const
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"CMAKE_PREFIX_PATH", "OPENRTM_DIR", "LD_LIBRARY_PATH", "PKG_CONFIG_PATH",
                             "CMAKE_GENERATOR", "CXXFLAGS", "LDFLAGS"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("PATH"), prefix + QStringLiteral("/bin:") + env.value(QStringLiteral("PATH")));
    env.insert(QStringLiteral("PKG_CONFIG_PATH"), prefix + QStringLiteral("/lib/pkgconfig"));
    return env;
}

QStringList TestSdkIdlFlow::cflags() const
{
    const RunResult result = run(m_prefix + QStringLiteral("/bin/rtm2-config"), {QStringLiteral("--cflags")},
                                 environment(), m_workDir.path(), toolTimeoutMs);
    return result.ok() ? result.output.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts)
                       : QStringList();
}

void TestSdkIdlFlow::everyWrapperCompilesAsCxx11()
{
    // OpenRTM-aist's rtm/idl set, the extensions included: all of them in one translation unit, so
    // that two files declaring alike names (DataPort and DataPort_OpenRTM) must coexist too.
    const QStringList expected{"CameraCommonInterface", "DataPort", "DataPortUDP", "DataPort_OpenRTM",
                               "ExtendedFsmService", "ManipulatorCommonInterface_Common",
                               "ManipulatorCommonInterface_DataTypes", "ManipulatorCommonInterface_Middle",
                               "SharedMemory"};
    const QStringList skels = QDir(rtmIdl()).entryList({QStringLiteral("*Skel.h")}, QDir::Files, QDir::Name);
    QByteArray source;
    for (const QString &name : expected) {
        QVERIFY2(skels.contains(name + QStringLiteral("Skel.h")), qPrintable(name));
        for (const char *file : {"Skel.h", "Stub.h", ".hh", ".idl"})
            QVERIFY2(QFileInfo::exists(rtmIdl() + QLatin1Char('/') + name + QLatin1String(file)),
                     qPrintable(name + QLatin1String(file)));
    }
    for (const QString &skel : skels) {
        QString stub = skel;
        stub.replace(QStringLiteral("Skel.h"), QStringLiteral("Stub.h"));
        source += "#include <rtm/idl/" + skel.toUtf8() + ">\n#include <rtm/idl/" + stub.toUtf8() + ">\n";
    }
    source += "int main() { Img::TimedCameraImage i; JARA_ARM::TimedJointPos j; RTC::FsmStructure f;\n"
              "  RTC::OctetSeq o; OpenRTM::CdrData c; return int(i.error_code + j.pos.length() + o.length()\n"
              "  + c.length()) + (RTC::PORT_OK == RTC::PortStatus(0) ? 0 : 1); }\n";
    const QString file = m_workDir.filePath(QStringLiteral("everywrapper.cpp"));
    QVERIFY(writeText(file, source));
    const QStringList flags = cflags();
    QVERIFY(!flags.isEmpty());
    const RunResult compile = run(QStringLiteral(RTSTUDIO_CXX_COMPILER),
                                  QStringList{QStringLiteral("-std=gnu++11"), QStringLiteral("-fsyntax-only"),
                                              QStringLiteral("-Werror")}
                                      + flags + QStringList{file},
                                  environment(), m_workDir.path(), buildTimeoutMs);
    QVERIFY2(compile.ok(), qPrintable(failure(QStringLiteral("compiling every wrapper"), compile)));
}

void TestSdkIdlFlow::extensionSkelIncludesTheCoreSet()
{
    // As OpenRTM-aist builds them: the extension's server-side headers pull in the core set first.
    for (const char *name : {"CameraCommonInterface", "ManipulatorCommonInterface_DataTypes"}) {
        const QString skel = readText(rtmIdl() + QLatin1Char('/') + QLatin1String(name) + QStringLiteral("Skel.h"));
        const QString stub = readText(rtmIdl() + QLatin1Char('/') + QLatin1String(name) + QStringLiteral("Stub.h"));
        for (const char *core : {"BasicDataType", "InterfaceDataTypes", "RTC", "ExtendedFsmService"}) {
            const QString include = QStringLiteral("#include <rtm/idl/%1Skel.h>").arg(QLatin1String(core));
            QVERIFY2(skel.contains(include), qPrintable(QLatin1String(name) + QLatin1String(": ") + include));
            QVERIFY2(!stub.contains(include), qPrintable(QLatin1String(name) + QLatin1String(": ") + include));
        }
        QVERIFY(skel.indexOf(QStringLiteral("#include <rtm/idl/RTCSkel.h>"))
                < skel.indexOf(QStringLiteral("#include \"%1.hh\"").arg(QLatin1String(name))));
    }
    // A core Skel header pulls in no other IDL's, only its types' copyData() specialisations.
    const QString core = readText(rtmIdl() + QStringLiteral("/BasicDataTypeSkel.h"));
    QVERIFY(!core.contains(QRegularExpression(QStringLiteral("#include <rtm/idl/\\w+Skel\\.h>"))));
    QVERIFY(core.contains(QStringLiteral("#include <rtm/idl/BasicDataTypeUtil.h>")));
    QVERIFY(!readText(rtmIdl() + QStringLiteral("/BasicDataTypeStub.h")).contains(QStringLiteral("Util.h")));
}

void TestSdkIdlFlow::extensionLibraryNamesLink_data()
{
    QTest::addColumn<QString>("library");
    for (const char *name : {"rtmCamera2", "rtmManipulator2", "rtmCamera", "rtmManipulator"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

// The sanitizer suite instruments the SDK's libraries; a program linking them needs the sanitizer runtimes
// first, which that suite hands on in LDFLAGS (empty elsewhere).
static QStringList sanitizerLinkFlags()
{
    return qEnvironmentVariable("LDFLAGS").split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

// Linked by path alone, as find_library() hands it on, without -lrtstudio_rtm or a -L of the prefix.
void TestSdkIdlFlow::extensionLibraryNamesLink()
{
    QFETCH(QString, library);
    const QString object = m_workDir.filePath(QStringLiteral("extlib.o"));
    if (!QFileInfo::exists(object)) {
        const QString source = m_workDir.filePath(QStringLiteral("extlib.cpp"));
        QVERIFY(writeText(source, "#include <CameraCommonInterfaceSkel.h>\n"
                                  "#include <ManipulatorCommonInterface_MiddleSkel.h>\n#include <iostream>\n"
                                  "int main() { std::cout << Img::_tc_TimedCameraImage->id() << ' '\n"
                                  "  << JARA_ARM::ManipulatorCommonInterface_Middle::_PD_repoId << std::endl; }\n"));
        const RunResult compile = run(QStringLiteral(RTSTUDIO_CXX_COMPILER),
                                      QStringList{QStringLiteral("-c"), QStringLiteral("-o"), object} + cflags()
                                          + QStringList{source},
                                      environment(), m_workDir.path(), buildTimeoutMs);
        QVERIFY2(compile.ok(), qPrintable(failure(QStringLiteral("compile"), compile)));
    }
    const QString lib = m_prefix + QStringLiteral("/lib/lib") + library + QStringLiteral(".so");
    QVERIFY(QFileInfo::exists(lib));
    const QString program = m_workDir.filePath(QStringLiteral("extlib-") + library);
    const RunResult link = run(QStringLiteral(RTSTUDIO_CXX_COMPILER),
                               QStringList{QStringLiteral("-o"), program, object, lib, QStringLiteral("-lomniORB4"),
                                QStringLiteral("-lomniDynamic4"), QStringLiteral("-lomnithread"),
                                QStringLiteral("-pthread"), QStringLiteral("-Wl,-rpath,") + m_prefix + QStringLiteral("/lib")}
                                   + sanitizerLinkFlags(),
                               environment(), m_workDir.path(), buildTimeoutMs);
    QVERIFY2(link.ok(), qPrintable(failure(QStringLiteral("link with ") + lib, link)));
    const RunResult probe = run(program, {}, environment(), m_workDir.path(), toolTimeoutMs);
    QVERIFY2(probe.ok(), qPrintable(failure(program, probe)));
    QCOMPARE(probe.output.trimmed(),
             QStringLiteral("IDL:Img/TimedCameraImage:1.0 IDL:JARA_ARM/ManipulatorCommonInterface_Middle:1.0"));
}

bool TestSdkIdlFlow::wrap(const QString &folder, const QStringList &arguments, QString *message)
{
    const QString dir = m_workDir.filePath(folder);
    QDir().mkpath(dir);
    const RunResult result = run(QStringLiteral("python3"),
                                 QStringList{m_prefix + QStringLiteral("/bin/rtm-skelwrapper")} + arguments,
                                 environment(), dir, toolTimeoutMs);
    if (!result.ok())
        *message = failure(QStringLiteral("rtm-skelwrapper ") + arguments.join(QLatin1Char(' ')), result);
    return result.ok();
}

void TestSdkIdlFlow::wrapperWritesIntoTheCurrentFolder()
{
    QString message;
    QVERIFY2(wrap(QStringLiteral("plain"),
                  {QStringLiteral("--include-dir="), QStringLiteral("--skel-suffix=Skel"),
                   QStringLiteral("--stub-suffix=Stub"), QStringLiteral("--idl-file=Relay.idl")},
                  &message),
             qPrintable(message));
    const QString dir = m_workDir.filePath(QStringLiteral("plain/"));
    QCOMPARE(QDir(dir).entryList(QDir::Files, QDir::Name),
             (QStringList{"RelaySkel.cpp", "RelaySkel.h", "RelayStub.cpp", "RelayStub.h"}));
    const QString skel = readText(dir + QStringLiteral("RelaySkel.h"));
    QVERIFY(skel.contains(QStringLiteral("#ifndef RELAYSKEL_H")));
    QVERIFY(skel.indexOf(QStringLiteral("#include <rtm/config_rtc.h>")) < skel.indexOf(QStringLiteral("#include \"Relay.hh\"")));
    QVERIFY(readText(dir + QStringLiteral("RelayStub.h")).contains(QStringLiteral("#include \"Relay.hh\"")));
    for (const char *source : {"RelaySkel.cpp", "RelayStub.cpp"}) {
        const QString text = readText(dir + QLatin1String(source));
        QVERIFY(text.contains(QStringLiteral("#include \"RelaySK.cc\"")));
        QVERIFY(text.contains(QStringLiteral("#include \"RelayDynSK.cc\"")));
    }

    // OpenRTM-aist's include guard carries the IDL file's folder.
    QVERIFY2(wrap(QStringLiteral("guard"), {QStringLiteral("--idl-file=../idl/Relay.idl")}, &message),
             qPrintable(message));
    QVERIFY(readText(m_workDir.filePath(QStringLiteral("guard/RelayStub.h"))).contains(QStringLiteral("#ifndef IDL_RELAYSTUB_H")));

    // Not an IDL file: nothing written, an error.
    QVERIFY(!wrap(QStringLiteral("wrong"), {QStringLiteral("--idl-file=Relay.txt")}, &message));
    QVERIFY(QDir(m_workDir.filePath(QStringLiteral("wrong"))).entryList(QDir::Files).isEmpty());
}

void TestSdkIdlFlow::wrapperIncludeDir_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("--include-dir=my/idl/") << QStringList{"--include-dir=my/idl/", "--idl-file=Relay.idl"};
    QTest::newRow("--include-dir=my/idl") << QStringList{"--include-dir=my/idl", "--idl-file=Relay.idl"};
    QTest::newRow("-I my/idl/ -f") << QStringList{"-I", "my/idl/", "-f", "Relay.idl"};
}

// omniidl's files are included through the folder given, with one slash, whether it ends in one
// (OpenRTM-aist's own users) or not.
void TestSdkIdlFlow::wrapperIncludeDir()
{
    QFETCH(QStringList, arguments);
    const QString folder = rowFolder("include");
    QString message;
    QVERIFY2(wrap(folder, arguments, &message), qPrintable(message));
    const QString dir = m_workDir.filePath(folder) + QLatin1Char('/');
    for (const QString &file : wrapperFiles()) {
        const QString text = readText(dir + file);
        QVERIFY2(!text.isEmpty(), qPrintable(file));
        QVERIFY2(!text.contains(QStringLiteral("my/idl//")) && !text.contains(QStringLiteral("my/idlRelay")), qPrintable(text));
        const QStringList expected = file.endsWith(QLatin1String(".h"))
                                         ? QStringList{QStringLiteral("#include \"my/idl/Relay.hh\"")}
                                         : QStringList{QStringLiteral("#include \"my/idl/RelaySK.cc\""),
                                                       QStringLiteral("#include \"my/idl/RelayDynSK.cc\"")};
        for (const QString &line : expected)
            QVERIFY2(text.contains(line), qPrintable(file + QLatin1String(": ") + line));
    }
    // The wrappers' own header is found beside them, not under the include folder.
    QVERIFY(readText(dir + QStringLiteral("RelaySkel.cpp")).contains(QStringLiteral("#include \"RelaySkel.h\"")));
}

void TestSdkIdlFlow::wrapperOutputDir_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("output");
    QTest::newRow("--output-dir=gen/") << QStringList{"--output-dir=gen/", "--idl-file=idl/Relay.idl"} << "gen";
    QTest::newRow("--output-dir=gen") << QStringList{"--output-dir=gen", "--idl-file=idl/Relay.idl"} << "gen";
    QTest::newRow("-o deeper/gen/") << QStringList{"-o", "deeper/gen/", "--idl-file=Relay.idl"} << "deeper/gen";
}

void TestSdkIdlFlow::wrapperOutputDir()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, output);
    const QString folder = rowFolder("output");
    QString message;
    QVERIFY2(wrap(folder, arguments, &message), qPrintable(message));
    const QString dir = m_workDir.filePath(folder);
    QCOMPARE(QDir(dir + QLatin1Char('/') + output).entryList(QDir::Files, QDir::Name),
             (QStringList{"RelaySkel.cpp", "RelaySkel.h", "RelayStub.cpp", "RelayStub.h"}));
    // Nothing beside the output folder.
    QCOMPARE(QDir(dir).entryList(QDir::Files), QStringList());
}

void TestSdkIdlFlow::wrapperDependenciesAndUtil()
{
    // Dependencies as OpenRTM-aist's CMake passes them (rtm/idl/<Name>, colon-separated): the server
    // side includes their Skel headers first; the client side does not.
    QString message;
    QVERIFY2(wrap(QStringLiteral("deps"),
                  {QStringLiteral("--idl-file=Relay.idl"), QStringLiteral("--skel-suffix=_Skel"),
                   QStringLiteral("--dependencies=rtm/idl/BasicDataType:rtm/idl/ExtendedDataTypes")},
                  &message),
             qPrintable(message));
    const QString dir = m_workDir.filePath(QStringLiteral("deps/"));
    const QString skel = readText(dir + QStringLiteral("Relay_Skel.h"));
    const int basic = skel.indexOf(QStringLiteral("#include <rtm/idl/BasicDataTypeSkel.h>"));
    const int extended = skel.indexOf(QStringLiteral("#include <rtm/idl/ExtendedDataTypesSkel.h>"));
    QVERIFY2(basic > 0 && extended > basic && skel.indexOf(QStringLiteral("#include \"Relay.hh\"")) > extended,
             qPrintable(skel));
    QVERIFY(!readText(dir + QStringLiteral("RelayStub.h")).contains(QStringLiteral("rtm/idl/")));
    QVERIFY(readText(dir + QStringLiteral("Relay_Skel.cpp")).contains(QStringLiteral("#include \"Relay_Skel.h\"")));
    QVERIFY(!skel.contains(QStringLiteral("RelayUtil")));

    // <Name>Util.h and .cpp in the include folder: the server side includes them as well.
    const QString util = m_workDir.filePath(QStringLiteral("util/types"));
    QVERIFY(QDir().mkpath(util));
    QVERIFY(writeText(util + QStringLiteral("/RelayUtil.h"), "// helpers\n"));
    QVERIFY(writeText(util + QStringLiteral("/RelayUtil.cpp"), "// helpers\n"));
    QVERIFY2(wrap(QStringLiteral("util"), {QStringLiteral("--idl-file=Relay.idl"), QStringLiteral("--include-dir=types/")},
                  &message),
             qPrintable(message));
    QVERIFY(readText(m_workDir.filePath(QStringLiteral("util/RelaySkel.h"))).contains(QStringLiteral("#include \"types/RelayUtil.h\"")));
    QVERIFY(readText(m_workDir.filePath(QStringLiteral("util/RelaySkel.cpp"))).contains(QStringLiteral("#include \"types/RelayUtil.cpp\"")));
    QVERIFY(!readText(m_workDir.filePath(QStringLiteral("util/RelayStub.h"))).contains(QStringLiteral("RelayUtil")));
    QVERIFY(!readText(m_workDir.filePath(QStringLiteral("util/RelayStub.cpp"))).contains(QStringLiteral("RelayUtil")));
}

void TestSdkIdlFlow::project_data()
{
    QTest::addColumn<QString>("fixture");
    QTest::addColumn<QString>("program");
    QTest::addColumn<bool>("prefixPath");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<bool>("installed");
    // find_package(OpenRTM) finds the prefix from the PATH (<prefix>/bin) unless told; rtm-config
    // comes from the PATH too.
    for (const bool installed : {false, true}) {
        const char *kind = installed ? "installed" : "build tree";
        QTest::addRow("OpenRTP 1.2: idl/ with rtm-config and rtm-skelwrapper, %s", kind)
            << "openrtp12" << "RelayProbe" << false << "openrtp12 2.1.0 1250mm 7 IDL:Relay/TimedReading:1.0"
            << installed;
        QTest::addRow("OpenRTP 2.0: idl/ sub-project, %s", kind)
            << "openrtp20" << "RelayProbe" << true << "openrtp20 2.1.0 1250mm 7 IDL:Relay/TimedReading:1.0"
            << installed;
        QTest::addRow("hand-written: --include-dir and --output-dir, %s", kind)
            << "includedir" << "RangerProbe" << false << "includedir 4.5 30 IDL:Sensors/TimedRange:1.0" << installed;
        QTest::addRow("extension IDL: camera and manipulator, %s", kind)
            << "extension" << "ExtensionProbe" << true
            << "extension 4x2 gray=1 px7=70 m33=1 joints=3 j1=-1.25 ok=0 arm:grip" << installed;
    }
}

void TestSdkIdlFlow::project()
{
    QFETCH(QString, fixture);
    QFETCH(QString, program);
    QFETCH(bool, prefixPath);
    QFETCH(QString, expected);
    QFETCH(bool, installed);
    const QString root = installed ? m_installPrefix : m_prefix;
    const QString source = (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdkidlflow/")) + fixture;
    const QString binary = m_workDir.filePath(QStringLiteral("project-") + fixture
                                              + (installed ? QStringLiteral("-installed") : QString()));
    const QProcessEnvironment env = environment(root);
    const QString cmake = QStringLiteral(RTSTUDIO_CMAKE_COMMAND);
    QStringList arguments{QStringLiteral("-S"), source, QStringLiteral("-B"), binary,
                          QStringLiteral("-G"), QStringLiteral(RTSTUDIO_CMAKE_GENERATOR),
                          QStringLiteral("-DCMAKE_MAKE_PROGRAM=" RTSTUDIO_CMAKE_MAKE_PROGRAM),
                          QStringLiteral("-DCMAKE_CXX_COMPILER=" RTSTUDIO_CXX_COMPILER)};
    if (prefixPath)
        arguments << QStringLiteral("-DCMAKE_PREFIX_PATH=") + root;
    const RunResult configure = run(cmake, arguments, env, m_workDir.path(), configureTimeoutMs);
    QVERIFY2(configure.ok(), qPrintable(failure(QStringLiteral("configure"), configure)));
    const RunResult build = run(cmake, {QStringLiteral("--build"), binary, QStringLiteral("-j"), QStringLiteral("2")},
                                env, m_workDir.path(), buildTimeoutMs);
    QVERIFY2(build.ok(), qPrintable(failure(QStringLiteral("build"), build)));

    // The executable lands in the build folder or, for OpenRTP's layouts, in src/.
    QString path = binary + QLatin1Char('/') + program;
    if (!QFileInfo::exists(path))
        path = binary + QStringLiteral("/src/") + program;
    const RunResult probe = run(path, {}, env, binary, toolTimeoutMs);
    QVERIFY2(probe.ok(), qPrintable(failure(program, probe)));
    QCOMPARE(probe.output.trimmed(), expected);
}

QTEST_GUILESS_MAIN(TestSdkIdlFlow)
#include "tst_sdkidlflow.moc"
