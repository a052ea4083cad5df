// SPDX-License-Identifier: MIT
// The component SDK's prefix (sdk/package/) as users consume it: the layout, the CMake package's
// variables, rtm-config, pkg-config and the skeleton wrapper, and small projects in five styles
// (OpenRTP 2.0, the 1.2 era, modern CMake, plain pkg-config, older include paths such as
// <coil-2.0/coil/…> and hrtm/…) configured, built and run against the build tree's prefix and
// against an installed copy made once per run with cmake --install.
#include "sdkproject.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
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

QString canonical(const QString &path)
{
    return QFileInfo(path).canonicalFilePath();
}

QString dataDir(const QString &project)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdkpackage/")) + project;
}

QStringList headerNames(const QString &folder)
{
    return QDir(folder).entryList({QStringLiteral("*.h")}, QDir::Files, QDir::Name);
}

} // namespace

class TestSdkPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void layout_data();
    void layout();
    void cmakePackage_data();
    void cmakePackage();
    void prefixThatTemplatesSplitIsReported();
    void rtmConfig_data();
    void rtmConfig();
    void pkgConfig_data();
    void pkgConfig();
    void skelWrapper();
    void consume_data();
    void consume();

private:
    void addPrefixRows();
    QString prefix(const QString &kind) const;
    QProcessEnvironment environment(const QString &prefix) const;

    QTemporaryDir m_installDir{QDir::tempPath() + QStringLiteral("/rtsdkinstallXXXXXX")};
    QTemporaryDir m_workDir{QDir::tempPath() + QStringLiteral("/rtsdkworkXXXXXX")};
    QString m_buildPrefix;
    QString m_installPrefix;
};

void TestSdkPackage::initTestCase()
{
    QVERIFY(m_installDir.isValid());
    QVERIFY(m_workDir.isValid());
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("python3")).isEmpty(),
             "python3 (which omniidl needs too) is missing");
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("omniidl")).isEmpty(), "omniidl is missing");
    QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("pkg-config")).isEmpty(), "pkg-config is missing");
    m_buildPrefix = canonical(RTSTUDIO_BUILD_DIR);
    QVERIFY2(QFileInfo::exists(m_buildPrefix + QStringLiteral("/lib/librtstudio_rtm.so")),
             "build the targets rtsdk and rtsdk_stage first");

    // The SDK's own component: it needs only what the SDK builds, not the applications.
    m_installPrefix = canonical(m_installDir.path());
    const RunResult install = run(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                                  {QStringLiteral("--install"), RTSTUDIO_BUILD_DIR,
                                   QStringLiteral("--prefix"), m_installPrefix, QStringLiteral("--component"),
                                   QStringLiteral("sdk")},
                                  QProcessEnvironment::systemEnvironment(), m_workDir.path(), buildTimeoutMs);
    QVERIFY2(install.ok(), qPrintable(failure(QStringLiteral("cmake --install"), install)));
}

void TestSdkPackage::addPrefixRows()
{
    QTest::addColumn<QString>("kind");
    QTest::newRow("build tree") << QStringLiteral("build");
    QTest::newRow("installed") << QStringLiteral("installed");
}

QString TestSdkPackage::prefix(const QString &kind) const
{
    return kind == QLatin1String("build") ? m_buildPrefix : m_installPrefix;
}

// What a user's shell has after adding the prefix: its bin on PATH, its pkg-config folder, nothing
// from the surrounding build.
QProcessEnvironment TestSdkPackage::environment(const QString &prefix) const
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"CMAKE_PREFIX_PATH", "OPENRTM_DIR", "LD_LIBRARY_PATH", "PKG_CONFIG_PATH",
                             "CMAKE_GENERATOR", "CXXFLAGS", "LDFLAGS"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("PATH"), prefix + QStringLiteral("/bin:") + env.value(QStringLiteral("PATH")));
    env.insert(QStringLiteral("PKG_CONFIG_PATH"), prefix + QStringLiteral("/lib/pkgconfig"));
    return env;
}

void TestSdkPackage::layout_data()
{
    addPrefixRows();
}

void TestSdkPackage::layout()
{
    QFETCH(QString, kind);
    const QString root = prefix(kind);
    const QString rtm = root + QStringLiteral("/include/openrtm-2.1/rtm");
    for (const char *file :
         {"include/openrtm-2.1/rtm/config_rtc.h", "include/openrtm-2.1/rtm/version.h",
          "include/coil-2.1/coil/config_coil.h", "include/coil-2.0/coil/config_coil.h",
          "lib/librtstudio_rtm.so", "lib/librtmCamera2.so", "lib/librtmManipulator2.so", "lib/librtmCamera.so",
          "lib/librtmManipulator.so", "lib/cmake/openrtm-2.1/OpenRTMConfig.cmake",
          "lib/cmake/openrtm-2.1/OpenRTMConfigVersion.cmake", "lib/pkgconfig/openrtm2.pc",
          "lib/pkgconfig/openrtm-aist.pc", "lib/pkgconfig/libcoil.pc"})
        QVERIFY2(QFileInfo(root + QLatin1Char('/') + QLatin1String(file)).isFile(), file);
    for (const char *folder : {"include/openrtm-2.1/rtm/ext", "share/openrtm-2.1"})
        QVERIFY2(QFileInfo(root + QLatin1Char('/') + QLatin1String(folder)).isDir(), folder);
    for (const char *tool : {"rtm2-config", "rtm-config", "rtm2-skelwrapper", "rtm-skelwrapper"})
        QVERIFY2(QFileInfo(root + QStringLiteral("/bin/") + QLatin1String(tool)).isExecutable(), tool);

    // Every public header of the SDK, and for every bundled IDL file the file itself, omniidl's
    // header and both wrappers.
    const QString sources = RTSTUDIO_SOURCE_DIR + QStringLiteral("/sdk/include/");
    QStringList staged = headerNames(rtm);
    staged.removeAll(QStringLiteral("config_rtc.h"));
    staged.removeAll(QStringLiteral("version.h"));
    QCOMPARE(staged, headerNames(sources + QStringLiteral("rtm")));
    QCOMPARE(headerNames(root + QStringLiteral("/include/coil-2.1/coil")), headerNames(sources + QStringLiteral("coil")));
    QCOMPARE(headerNames(root + QStringLiteral("/include/coil-2.0/coil")), headerNames(sources + QStringLiteral("coil")));
    // HRTM's headers where OpenRTM-aist installs them.
    QCOMPARE(headerNames(root + QStringLiteral("/include/openrtm-2.1/hrtm")), headerNames(sources + QStringLiteral("hrtm")));
    QCOMPARE(headerNames(root + QStringLiteral("/include/openrtm-2.1/hrtm/idls")),
             headerNames(sources + QStringLiteral("hrtm/idls")));
    QVERIFY(!headerNames(sources + QStringLiteral("hrtm/idls")).isEmpty());
    // The component API's headers reach the runtime's as <rtmruntime/…>.
    QCOMPARE(headerNames(root + QStringLiteral("/include/openrtm-2.1/rtmruntime")),
             headerNames(RTSTUDIO_SOURCE_DIR + QStringLiteral("/manager")));
    const QStringList idlFiles = QDir(RTSTUDIO_SOURCE_DIR + QStringLiteral("/corba/idl"))
                                     .entryList({QStringLiteral("*.idl")}, QDir::Files);
    QVERIFY(idlFiles.contains(QStringLiteral("BasicDataType.idl")));
    for (const QString &idl : idlFiles) {
        const QString name = QFileInfo(idl).completeBaseName();
        for (const QString &file : {idl, name + QStringLiteral(".hh"), name + QStringLiteral("Skel.h"),
                                    name + QStringLiteral("Stub.h")})
            QVERIFY2(QFileInfo::exists(rtm + QStringLiteral("/idl/") + file), qPrintable(file));
    }
}

void TestSdkPackage::cmakePackage_data()
{
    addPrefixRows();
}

void TestSdkPackage::cmakePackage()
{
    QFETCH(QString, kind);
    const QString root = prefix(kind);
    const RunResult configure = run(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                                    {QStringLiteral("-S"), dataDir(QStringLiteral("variables")), QStringLiteral("-B"),
                                     m_workDir.filePath(QStringLiteral("variables-") + kind),
                                     QStringLiteral("-DCMAKE_PREFIX_PATH=") + root},
                                    environment(root), m_workDir.path(), configureTimeoutMs);
    QVERIFY2(configure.ok(), qPrintable(failure(QStringLiteral("configure"), configure)));
    QHash<QString, QString> vars;
    static const QRegularExpression line(QStringLiteral("^-- SDKVAR ([^=]+)=(.*)$"),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(configure.output); it.hasNext();) {
        const QRegularExpressionMatch match = it.next();
        vars.insert(match.captured(1), match.captured(2));
    }

    const QString rtm = root + QStringLiteral("/include/openrtm-2.1");
    const QStringList includeDirs{root + QStringLiteral("/include"), root + QStringLiteral("/include/coil-2.1"), rtm,
                                  rtm + QStringLiteral("/rtm/idl"), rtm + QStringLiteral("/rtm/ext")};
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_DIR")), root);
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_INCLUDE_DIRS")), includeDirs.join(QLatin1Char(';')));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_LIBRARY_DIRS")), root + QStringLiteral("/lib"));
    // A build with sanitizers adds their flags, which every program linking the SDK needs.
    const QStringList linkFlags = QStringLiteral(RTSDK_LINK_FLAGS).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_LIBRARIES")),
             (QStringList {"rtstudio_rtm", "omniORB4", "omniDynamic4", "omnithread", "pthread"} + linkFlags)
                 .join(QLatin1Char(';')));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_CFLAGS")), QStringLiteral("-Wall;-fPIC;-O2"));
    QVERIFY(vars.contains(QStringLiteral("OPENRTM_LDFLAGS")));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_INCLUDE_DIR")), rtm);
    QCOMPARE(vars.value(QStringLiteral("COIL_INCLUDE_DIR")), root + QStringLiteral("/include/coil-2.1"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_LIB_DIR")), root + QStringLiteral("/lib"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_DATA_DIR")), root + QStringLiteral("/share/openrtm-2.1"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_VERSION")), QStringLiteral("2.1.0"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_VERSION_MAJOR")), QStringLiteral("2"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_VERSION_MINOR")), QStringLiteral("1"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_VERSION_PATCH")), QStringLiteral("0"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_SHORT_VERSION")), QStringLiteral("210"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_ORB")), QStringLiteral("omniORB"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_IDLC")), QStringLiteral("omniidl"));
    QVERIFY2(vars.value(QStringLiteral("OPENRTM_IDLFLAGS"))
                 .startsWith(QStringLiteral("-bcxx;-Wba;-nf;-Wbuse_quotes;-Wbshortcut;-I") + rtm
                             + QStringLiteral("/rtm/idl")),
             qPrintable(vars.value(QStringLiteral("OPENRTM_IDLFLAGS"))));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_IDL_WRAPPER")), QStringLiteral("rtm2-skelwrapper"));
    QCOMPARE(vars.value(QStringLiteral("OPENRTM_IDL_WRAPPER_FLAGS")),
             QStringLiteral("--include-dir=;--skel-suffix=Skel;--stub-suffix=Stub"));
    QCOMPARE(vars.value(QStringLiteral("RTSTUDIO_SDK")), QStringLiteral("TRUE"));
    QCOMPARE(vars.value(QStringLiteral("target OpenRTM::RTC")), root + QStringLiteral("/lib/librtstudio_rtm.so"));
    QCOMPARE(vars.value(QStringLiteral("OpenRTM 3 found")), QStringLiteral("0"));
}

void TestSdkPackage::prefixThatTemplatesSplitIsReported()
{
    // The package file derives the prefix from where it lies; a copy under a folder named with "-I"
    // stands for an SDK installed there.
    const QString moved = m_workDir.filePath(QStringLiteral("sdk-Include"));
    const QString packageDir = QStringLiteral("/lib/cmake/openrtm-2.1");
    QVERIFY(QDir().mkpath(moved + packageDir));
    for (const QString &file : QDir(m_installPrefix + packageDir).entryList(QDir::Files))
        QVERIFY(QFile::copy(m_installPrefix + packageDir + QLatin1Char('/') + file,
                            moved + packageDir + QLatin1Char('/') + file));
    const RunResult configure = run(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                                    {QStringLiteral("-S"), dataDir(QStringLiteral("variables")), QStringLiteral("-B"),
                                     m_workDir.filePath(QStringLiteral("variables-moved")),
                                     QStringLiteral("-DCMAKE_PREFIX_PATH=") + moved},
                                    environment(moved), m_workDir.path(), configureTimeoutMs);
    QVERIFY2(configure.ok(), qPrintable(failure(QStringLiteral("configure"), configure)));
    QVERIFY2(configure.output.contains(QStringLiteral("contains \"-I\"")), qPrintable(configure.output));
    QVERIFY2(configure.output.contains(moved), qPrintable(configure.output));

    // Where the prefix has none of them, nothing is said.
    const RunResult plain = run(QStringLiteral(RTSTUDIO_CMAKE_COMMAND),
                                {QStringLiteral("-S"), dataDir(QStringLiteral("variables")), QStringLiteral("-B"),
                                 m_workDir.filePath(QStringLiteral("variables-plain")),
                                 QStringLiteral("-DCMAKE_PREFIX_PATH=") + m_installPrefix},
                                environment(m_installPrefix), m_workDir.path(), configureTimeoutMs);
    QVERIFY2(plain.ok(), qPrintable(failure(QStringLiteral("configure"), plain)));
    QVERIFY2(!plain.output.contains(QStringLiteral("OpenRTP split")), qPrintable(plain.output));
}

void TestSdkPackage::rtmConfig_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("tool");
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("expected"); // "@" stands for the prefix
    const QList<QPair<const char *, const char *>> options{
        {"--prefix", "@"},
        {"--exec-prefix", "@"},
        {"--version", "2.1.0"},
        {"--idlc", "omniidl"},
        {"--libs-only-l", "-lrtstudio_rtm -lomniORB4 -lomniDynamic4 -lomnithread -lpthread" RTSDK_LINK_FLAGS},
        {"--libs-only-L", "-L@/lib"},
        {"--rtm-includedir", "@/include/openrtm-2.1"},
        {"--rtm-idldir", "@/include/openrtm-2.1/rtm/idl"},
        {"--rtm-libdir", "@/lib"},
        {"--rtm-datadir", "@/share/openrtm-2.1"},
        {"--coil-includedir", "@/include/coil-2.1"},
        {"--cflags", "-Wall -fPIC -O2 -I@/include -I@/include/coil-2.1 -I@/include/openrtm-2.1 "
                     "-I@/include/openrtm-2.1/rtm/idl -I@/include/openrtm-2.1/rtm/ext"}};
    for (const char *kind : {"build", "installed"}) {
        for (const char *tool : {"rtm2-config", "rtm-config"}) {
            for (const auto &[option, expected] : options)
                QTest::addRow("%s %s %s", kind, tool, option) << kind << tool << option << expected;
        }
        QTest::addRow("%s idlflags", kind) << kind << "rtm2-config" << "--idlflags"
                                          << "-bcxx -Wba -nf -Wbshortcut -I@/include/openrtm-2.1/rtm/idl";
    }
}

void TestSdkPackage::rtmConfig()
{
    QFETCH(QString, kind);
    QFETCH(QString, tool);
    QFETCH(QString, option);
    QFETCH(QString, expected);
    const QString root = prefix(kind);
    const RunResult result = run(root + QStringLiteral("/bin/") + tool, {option}, environment(root), m_workDir.path(),
                                 toolTimeoutMs);
    QVERIFY2(result.ok(), qPrintable(failure(tool, result)));
    const QString want = expected.replace(QLatin1Char('@'), root);
    // --idlflags may add omniORB's own IDL folder after the SDK's.
    if (option == QLatin1String("--idlflags"))
        QVERIFY2(result.output.trimmed().startsWith(want), qPrintable(result.output));
    else
        QCOMPARE(result.output.trimmed(), want);
}

void TestSdkPackage::pkgConfig_data()
{
    addPrefixRows();
}

void TestSdkPackage::pkgConfig()
{
    QFETCH(QString, kind);
    const QString root = prefix(kind);
    const QProcessEnvironment env = environment(root);
    const QString pkgConfig = QStringLiteral("pkg-config");
    const RunResult versions = run(pkgConfig,
                                   {QStringLiteral("--modversion"), QStringLiteral("openrtm2"),
                                    QStringLiteral("openrtm-aist"), QStringLiteral("libcoil")},
                                   env, m_workDir.path(), toolTimeoutMs);
    QVERIFY2(versions.ok(), qPrintable(failure(QStringLiteral("pkg-config --modversion"), versions)));
    QCOMPARE(versions.output.split(QLatin1Char('\n'), Qt::SkipEmptyParts),
             QStringList(3, QStringLiteral("2.1.0")));
    for (const char *module : {"openrtm2", "openrtm-aist"}) {
        const RunResult idlDir = run(pkgConfig, {QStringLiteral("--variable=rtm_idldir"), QLatin1String(module)},
                                     env, m_workDir.path(), toolTimeoutMs);
        QVERIFY2(idlDir.ok(), qPrintable(failure(QStringLiteral("pkg-config --variable"), idlDir)));
        QCOMPARE(canonical(idlDir.output.trimmed()), root + QStringLiteral("/include/openrtm-2.1/rtm/idl"));
    }
    const RunResult coil = run(pkgConfig, {QStringLiteral("--cflags"), QStringLiteral("--libs"), QStringLiteral("libcoil")},
                               env, m_workDir.path(), toolTimeoutMs);
    QVERIFY2(coil.ok(), qPrintable(failure(QStringLiteral("pkg-config libcoil"), coil)));
    QVERIFY2(coil.output.contains(QStringLiteral("/include/coil-2.1")), qPrintable(coil.output));
    QVERIFY2(coil.output.contains(QStringLiteral("-lrtstudio_rtm")), qPrintable(coil.output));
}

void TestSdkPackage::skelWrapper()
{
    const QString bin = m_installPrefix + QStringLiteral("/bin/");
    const QString out = m_workDir.filePath(QStringLiteral("skelwrapper"));
    QVERIFY(QDir().mkpath(out));
    const QProcessEnvironment env = environment(m_installPrefix);

    // As 1.2-era projects call it, writing into the current folder.
    const QStringList legacyArguments{bin + QStringLiteral("rtm-skelwrapper"), QStringLiteral("--include-dir="),
                                      QStringLiteral("--skel-suffix=Skel"), QStringLiteral("--stub-suffix=Stub"),
                                      QStringLiteral("--idl-file=Greeting.idl")};
    RunResult result = run(QStringLiteral("python3"), legacyArguments, env, out, toolTimeoutMs);
    QVERIFY2(result.ok(), qPrintable(failure(QStringLiteral("rtm-skelwrapper"), result)));
    const auto read = [&out](const QString &name) {
        QFile file(out + QLatin1Char('/') + name);
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    };
    for (const char *name : {"GreetingSkel.h", "GreetingStub.h"}) {
        const QString header = read(QLatin1String(name));
        QVERIFY2(header.contains(QStringLiteral("#include <rtm/config_rtc.h>")), name);
        QVERIFY2(header.contains(QStringLiteral("#include \"Greeting.hh\"")), name);
    }
    for (const char *name : {"GreetingSkel.cpp", "GreetingStub.cpp"}) {
        const QString source = read(QLatin1String(name));
        QVERIFY2(source.contains(QStringLiteral("#include \"GreetingSK.cc\"")), name);
        QVERIFY2(source.contains(QStringLiteral("#include \"GreetingDynSK.cc\"")), name);
    }
    QVERIFY(read(QStringLiteral("GreetingSkel.cpp")).contains(QStringLiteral("#include \"GreetingSkel.h\"")));

    // Run again unchanged: the files keep their times, so builds that always run it stay incremental.
    const QDateTime written = QFileInfo(out + QStringLiteral("/GreetingSkel.h")).lastModified();
    result = run(QStringLiteral("python3"), legacyArguments, env, out, toolTimeoutMs);
    QVERIFY(result.ok());
    QCOMPARE(QFileInfo(out + QStringLiteral("/GreetingSkel.h")).lastModified(), written);

    // As its own program, with an include prefix and an output folder.
    result = run(bin + QStringLiteral("rtm2-skelwrapper"),
                 {QStringLiteral("--idl-file=idl/Ranger.idl"), QStringLiteral("--include-dir=my/idl"),
                  QStringLiteral("--output-dir=gen")},
                 env, out, toolTimeoutMs);
    QVERIFY2(result.ok(), qPrintable(failure(QStringLiteral("rtm2-skelwrapper"), result)));
    QVERIFY(read(QStringLiteral("gen/RangerStub.h")).contains(QStringLiteral("#include \"my/idl/Ranger.hh\"")));
    QVERIFY(read(QStringLiteral("gen/RangerSkel.cpp")).contains(QStringLiteral("#include \"my/idl/RangerSK.cc\"")));

    result = run(bin + QStringLiteral("rtm2-skelwrapper"), {QStringLiteral("--idl-file=Ranger.txt")}, env, out,
                 toolTimeoutMs);
    QVERIFY(result.finished);
    QVERIFY(result.exitCode != 0);
}

void TestSdkPackage::consume_data()
{
    QTest::addColumn<QString>("style");
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("expected");
    const QList<QList<const char *>> styles{
        {"openrtp2", "GreetingProbe", "openrtp2 2.1.0 HELLO 42 2"},
        {"legacy12", "LegacyProbe", "legacy12 2.1 legacy 3 -2 1s500000us ticked"},
        {"modern", "ModernProbe", "modern 2.1.0 sdk=1 3 4 0.5 rate=1000"},
        {"pkgconfig", "PkgConfigProbe", "pkgconfig 2.1.0 pkg-config 2"},
        {"olderpaths", "OlderPathsProbe", "olderpaths 2.1.0 ticks=3 key=value 1.5 hrtm=0.6.13"}};
    for (const char *kind : {"build", "installed"}) {
        for (const auto &style : styles)
            QTest::addRow("%s %s", style[0], kind) << style[0] << kind << style[1] << style[2];
    }
}

// Configures, builds and runs one style's project the way its users would.
void TestSdkPackage::consume()
{
    QFETCH(QString, style);
    QFETCH(QString, kind);
    QFETCH(QString, program);
    QFETCH(QString, expected);
    const QString root = prefix(kind);
    if (style == QLatin1String("openrtp2") && root.contains(QRegularExpression(QStringLiteral("-[lLI]"))))
        QSKIP("OpenRTP's templates split paths at -l, -L and -I; this prefix contains one");
    const QString source = dataDir(style);
    const QString binary = m_workDir.filePath(style + QLatin1Char('-') + kind);
    QProcessEnvironment env = environment(root);
    const QString cmake = QStringLiteral(RTSTUDIO_CMAKE_COMMAND);

    if (style == QLatin1String("pkgconfig")) {
        QVERIFY(QDir().mkpath(binary));
        const RunResult build = run(QStringLiteral("sh"), {source + QStringLiteral("/build.sh"), binary + QLatin1Char('/') + program},
                                    env, binary, buildTimeoutMs);
        QVERIFY2(build.ok(), qPrintable(failure(QStringLiteral("build.sh"), build)));
        // No rpath on a bare command line: the loader is told where the prefix's library is.
        env.insert(QStringLiteral("LD_LIBRARY_PATH"), root + QStringLiteral("/lib"));
    } else {
        QStringList arguments{QStringLiteral("-S"), source, QStringLiteral("-B"), binary,
                              QStringLiteral("-G"), QStringLiteral(RTSTUDIO_CMAKE_GENERATOR),
                              QStringLiteral("-DCMAKE_MAKE_PROGRAM=" RTSTUDIO_CMAKE_MAKE_PROGRAM),
                              QStringLiteral("-DCMAKE_CXX_COMPILER=" RTSTUDIO_CXX_COMPILER)};
        // 1.2-era projects find rtm-config on the PATH instead.
        if (style != QLatin1String("legacy12"))
            arguments << QStringLiteral("-DCMAKE_PREFIX_PATH=") + root;
        const RunResult configure = run(cmake, arguments, env, m_workDir.path(), configureTimeoutMs);
        QVERIFY2(configure.ok(), qPrintable(failure(QStringLiteral("configure"), configure)));
        const RunResult build = run(cmake, {QStringLiteral("--build"), binary, QStringLiteral("-j"), QStringLiteral("2")},
                                    env, m_workDir.path(), buildTimeoutMs);
        QVERIFY2(build.ok(), qPrintable(failure(QStringLiteral("build"), build)));
    }

    const RunResult probe = run(binary + QLatin1Char('/') + program, {}, env, binary, toolTimeoutMs);
    QVERIFY2(probe.ok(), qPrintable(failure(program, probe)));
    QCOMPARE(probe.output.trimmed(), expected);
}

QTEST_GUILESS_MAIN(TestSdkPackage)
#include "tst_sdkpackage.moc"
