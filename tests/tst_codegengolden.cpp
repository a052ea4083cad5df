// SPDX-License-Identifier: MIT
#include "codegenerator.h"
#include "idltypelibrary.h"
#include "profileio.h"
#include "projectwriter.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <map>
#include <memory>

using namespace Codegen;
using namespace Profile;

// The generated projects of the fixture components (tests/data/codegen/<Name>.xml), byte for
// byte against tests/data/codegen/golden/<Name>/, and checks with the real tools: Python's
// compiler on every .py file, omniidl + the C++ compiler on the servants, and CMake configuring
// every generated C++ tree against a stand-in OpenRTMConfig.cmake.
//
// To refresh the golden files after an intended change, run the test once with
// RTSTUDIO_UPDATE_GOLDEN=1 in the environment and review the diff; the test never rewrites
// them otherwise (and fails on any difference).
class TestCodegenGolden : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesGoldenFiles_data();
    void matchesGoldenFiles();
    void deterministic_data();
    void deterministic();
    void pythonCompiles_data();
    void pythonCompiles();
    void servantsCompileAgainstOmniidlSkeletons_data();
    void servantsCompileAgainstOmniidlSkeletons();
    void cmakeConfigures_data();
    void cmakeConfigures();
    void javaVectorHoldersParse();
    void vectorConvertOnlyWithVectorParameters_data();
    void vectorConvertOnlyWithVectorParameters();
    void cppVectorConvertReadsVectors();

private:
    void addFixtureRows();
    QString projectDir(const QString &fixture) const;
    void compileServants(const QString &root, const QString &component, int *compiled);
    std::map<QString, QList<GeneratedFile>> m_files;
    std::map<QString, std::unique_ptr<QTemporaryDir>> m_projects;
};

namespace {

// Each fixture covers one part of the generator: every kind of parameter mapping (SampleComp),
// data ports of many types, services from a multi-module IDL with inheritance, every
// configuration widget and constraint kind, and every documentation field.
const QStringList &fixtures()
{
    static const QStringList names = {QStringLiteral("SampleComp"), QStringLiteral("DataPortsComp"),
                                      QStringLiteral("ServicesComp"), QStringLiteral("ConfigComp"),
                                      QStringLiteral("DocumentedComp")};
    return names;
}

QString data(const QString &relative)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/")) + relative;
}

std::optional<QList<GeneratedFile>> generateFixture(const QString &fixture, QString *problems)
{
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded
        = loadProfileFile(data(fixture + QStringLiteral(".xml")), &diagnostics);
    std::optional<QList<GeneratedFile>> files;
    if (loaded && loaded->rtc) {
        IdlTypeLibrary library({RTSTUDIO_IDL_DIR, data(QStringLiteral("idl"))});
        CodeGenerator generator(*loaded->rtc, library.model());
        generator.setTestComponent(true);
        files = generator.generate(allTargetLanguages(), &diagnostics);
    }
    for (const Diagnostic &d : std::as_const(diagnostics))
        *problems += d.toString() + QLatin1Char('\n');
    return files;
}

bool run(const QString &program, const QStringList &arguments, const QString &dir, QString *output)
{
    QProcess process;
    process.setWorkingDirectory(dir);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool finished = process.waitForFinished(180000);
    *output = QString::fromLocal8Bit(process.readAll());
    return finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

QStringList filesUnder(const QString &dir, const QStringList &nameFilters)
{
    QStringList found;
    QDirIterator it(dir, nameFilters, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        found << QDir(dir).relativeFilePath(it.next());
    found.sort();
    return found;
}

void writeGolden(const QString &goldenDir, const QList<GeneratedFile> &files)
{
    QDir(goldenDir).removeRecursively();
    for (const GeneratedFile &file : files) {
        const QString path = QDir(goldenDir).filePath(file.path);
        QDir().mkpath(QFileInfo(path).absolutePath());
        QFile out(path);
        if (out.open(QIODevice::WriteOnly | QIODevice::Truncate))
            out.write(file.content);
        // Scripts are committed executable, as the project writer makes them.
        if (file.path.endsWith(QLatin1String(".sh")))
            out.setPermissions(out.permissions() | QFileDevice::ExeOwner | QFileDevice::ExeGroup
                               | QFileDevice::ExeOther);
    }
}

} // namespace

void TestCodegenGolden::initTestCase()
{
    for (const QString &fixture : fixtures()) {
        QString problems;
        const auto files = generateFixture(fixture, &problems);
        QVERIFY2(files, qPrintable(fixture + ": " + problems));
        m_files[fixture] = *files;
        auto dir = std::make_unique<QTemporaryDir>();
        QVERIFY(dir->isValid());
        Diagnostics diagnostics;
        QVERIFY(ProjectWriter(dir->path()).write(*files, &diagnostics));
        m_projects[fixture] = std::move(dir);
    }
}

void TestCodegenGolden::addFixtureRows()
{
    QTest::addColumn<QString>("fixture");
    for (const QString &fixture : fixtures())
        QTest::newRow(qPrintable(fixture)) << fixture;
}

QString TestCodegenGolden::projectDir(const QString &fixture) const
{
    return m_projects.at(fixture)->path();
}

void TestCodegenGolden::matchesGoldenFiles_data()
{
    addFixtureRows();
}

void TestCodegenGolden::matchesGoldenFiles()
{
    QFETCH(QString, fixture);
    const QList<GeneratedFile> &files = m_files.at(fixture);
    const QDir golden(data(QStringLiteral("golden/") + fixture));
    if (qEnvironmentVariableIntValue("RTSTUDIO_UPDATE_GOLDEN") == 1)
        writeGolden(golden.path(), files);
    QStringList generated;
    for (const GeneratedFile &file : files) {
        generated << file.path;
        QFile expected(golden.filePath(file.path));
        QVERIFY2(expected.open(QIODevice::ReadOnly), qPrintable(file.path + " has no golden file"));
        const QList<QByteArray> want = expected.readAll().split('\n');
        const QList<QByteArray> got = file.content.split('\n');
        for (int i = 0; i < std::min(want.size(), got.size()); ++i)
            QVERIFY2(
                want.at(i) == got.at(i),
                qPrintable(QStringLiteral("%1:%2: expected '%3', generated '%4'")
                               .arg(file.path)
                               .arg(i + 1)
                               .arg(QString::fromUtf8(want.at(i)), QString::fromUtf8(got.at(i)))));
        QCOMPARE(got.size(), want.size());
    }
    // No golden file may be left over from files the generator no longer writes.
    generated.sort();
    QCOMPARE(generated, filesUnder(golden.path(), {}));
}

void TestCodegenGolden::deterministic_data()
{
    addFixtureRows();
}

void TestCodegenGolden::deterministic()
{
    QFETCH(QString, fixture);
    QString problems;
    const auto again = generateFixture(fixture, &problems);
    QVERIFY2(again, qPrintable(problems));
    QCOMPARE(*again, m_files.at(fixture));
}

void TestCodegenGolden::pythonCompiles_data()
{
    addFixtureRows();
}

void TestCodegenGolden::pythonCompiles()
{
    QFETCH(QString, fixture);
    const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
    if (python.isEmpty())
        QSKIP("python3 is not installed; the generated Python is not compiled");
    const QStringList scripts = filesUnder(projectDir(fixture), {QStringLiteral("*.py")});
    QVERIFY(scripts.contains(fixture + QStringLiteral(".py")));
    for (const QString &script : scripts) {
        QString output;
        QVERIFY2(run(python, {"-m", "py_compile", script}, projectDir(fixture), &output),
                 qPrintable(script + ": " + output));
    }
}

// Only the fixtures whose component or test component implements a service interface have servants.
void TestCodegenGolden::servantsCompileAgainstOmniidlSkeletons_data()
{
    QTest::addColumn<QString>("fixture");
    for (const QString &fixture : fixtures()) {
        QDirIterator it(projectDir(fixture), {QStringLiteral("*SVC_impl.cpp")}, QDir::Files,
                        QDirIterator::Subdirectories);
        if (it.hasNext())
            QTest::newRow(qPrintable(fixture)) << fixture;
    }
}

void TestCodegenGolden::servantsCompileAgainstOmniidlSkeletons()
{
    QFETCH(QString, fixture);
    const QString omniidl = QStandardPaths::findExecutable(QStringLiteral("omniidl"));
    const QString compiler = QStandardPaths::findExecutable(QStringLiteral("c++"));
    if (omniidl.isEmpty() || compiler.isEmpty())
        QSKIP("omniidl or c++ is not installed; the generated servants are not compiled");
    // The component's tree and the test component's, each a project of its own.
    int compiled = 0;
    const QDir project(projectDir(fixture));
    compileServants(project.path(), fixture, &compiled);
    if (QTest::currentTestFailed())
        return;
    if (project.exists(QStringLiteral("test")))
        compileServants(project.filePath("test"), fixture + QStringLiteral("Test"), &compiled);
    QVERIFY2(compiled > 0, "no servant was compiled");
}

void TestCodegenGolden::compileServants(const QString &root, const QString &component,
                                        int *compiled)
{
    const QDir tree(root);
    QStringList sources = filesUnder(tree.filePath("src"), {QStringLiteral("*SVC_impl.cpp")});
    if (sources.isEmpty())
        return;
    QTemporaryDir skeletons;
    QString output;
    // The project's IDL copies plus the OpenRTM data types they include, as the generated
    // idl/CMakeLists.txt compiles them.
    QStringList idls {RTSTUDIO_IDL_DIR + QStringLiteral("/BasicDataType.idl")};
    for (const QString &idl : filesUnder(tree.filePath("idl"), {QStringLiteral("*.idl")}))
        idls << tree.filePath(QStringLiteral("idl/") + idl);
    for (const QString &idl : std::as_const(idls))
        QVERIFY2(run(QStringLiteral("omniidl"),
                     {"-bcxx", "-Wba", "-Wbh=.hh", "-Wbs=SK.cc", "-Wbd=DynSK.cc",
                      QStringLiteral("-I") + RTSTUDIO_IDL_DIR, idl},
                     skeletons.path(), &output),
                 qPrintable(output));
    // A translation unit that creates every servant: instantiating one fails to compile unless
    // every operation of its interface (and all its bases) is implemented with the signature
    // omniidl's skeleton declares.
    const QString include = tree.filePath(QStringLiteral("include/") + component);
    QByteArray driver;
    QByteArray body;
    static const QRegularExpression classLine(QStringLiteral("^class (\\w+SVC_impl)$"),
                                              QRegularExpression::MultilineOption);
    for (const QString &header : filesUnder(include, {QStringLiteral("*SVC_impl.h")})) {
        QFile file(QDir(include).filePath(header));
        QVERIFY(file.open(QIODevice::ReadOnly));
        driver += "#include \"" + header.toUtf8() + "\"\n";
        auto it = classLine.globalMatch(QString::fromUtf8(file.readAll()));
        while (it.hasNext()) {
            const QByteArray name = it.next().captured(1).toUtf8();
            body += "  { " + name + " *s = new " + name + "(); s->_remove_ref(); }\n";
        }
    }
    QVERIFY2(!body.isEmpty(), qPrintable(include + " declares no servant class"));
    QFile file(skeletons.filePath("instantiate.cpp"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(driver + "int main()\n{\n" + body + "}\n");
    file.close();
    for (QString &source : sources)
        source = tree.filePath(QStringLiteral("src/") + source);
    sources << file.fileName();
    for (const QString &unit : std::as_const(sources))
        QVERIFY2(run(QStringLiteral("c++"),
                     {"-std=c++11", "-fsyntax-only", "-Wall", "-Wextra", "-Wno-unused-parameter",
                      "-Werror", "-I" + skeletons.path(), "-I" + include, unit},
                     skeletons.path(), &output),
                 qPrintable(unit + ":\n" + output));
    *compiled += int(sources.size());
}

void TestCodegenGolden::cmakeConfigures_data()
{
    addFixtureRows();
}

void TestCodegenGolden::cmakeConfigures()
{
    QFETCH(QString, fixture);
    const QString cmake = QStandardPaths::findExecutable(QStringLiteral("cmake"));
    // The project itself is built with CMake, so it is always there: its absence is a failure.
    QVERIFY2(!cmake.isEmpty(), "cmake not found on PATH");
    // The component project and, when generated, the test component's project beside it.
    QStringList trees {projectDir(fixture)};
    if (QFileInfo::exists(QDir(projectDir(fixture)).filePath("test/CMakeLists.txt")))
        trees << QDir(projectDir(fixture)).filePath("test");
    for (const QString &tree : std::as_const(trees)) {
        QTemporaryDir build;
        QString output;
        // Configure only: this parses every generated CMakeLists.txt and evaluates it against
        // the variables OpenRTM-aist's config defines, without needing OpenRTM-aist itself.
        QVERIFY2(
            run(cmake,
                {"-S", tree, "-B", build.path(), "-G", "Unix Makefiles",
                 "-DOpenRTM_DIR=" + data(QStringLiteral("openrtm")),
                 "-DOPENRTM_FIXTURE_PREFIX=" + build.path(), "--warn-uninitialized", "-Werror=dev"},
                build.path(), &output),
            qPrintable(tree + ":\n" + output));
        QVERIFY2(!output.contains(QLatin1String("CMake Warning")), qPrintable(output));
        QVERIFY(QFileInfo::exists(QDir(build.path()).filePath("Makefile")));
        // `cmake --install` puts the component's headers beside the module and the program.
        QFile rules(QDir(build.path()).filePath("src/cmake_install.cmake"));
        QVERIFY(rules.open(QIODevice::ReadOnly));
        const QString name
            = tree == projectDir(fixture) ? fixture : fixture + QStringLiteral("Test");
        QVERIFY2(rules.readAll().contains(QStringLiteral("/include/%1\"").arg(name).toUtf8()),
                 qPrintable(rules.fileName()));
    }
}

void TestCodegenGolden::javaVectorHoldersParse()
{
    const QString javac = QStandardPaths::findExecutable(QStringLiteral("javac"));
    const QString java = QStandardPaths::findExecutable(QStringLiteral("java"));
    if (javac.isEmpty() || java.isEmpty())
        QSKIP("no Java development kit; the generated vector holders are not compiled");
    const QDir project(projectDir(QStringLiteral("ConfigComp")));
    const QString standIns = data(QStringLiteral("openrtm/java"));
    QTemporaryDir classes;
    QString output;
    QVERIFY2(run(javac,
                 {"-d", classes.path(), project.filePath("src/DoubleVectorHolder.java"),
                  project.filePath("src/StringVectorHolder.java"),
                  standIns + "/jp/go/aist/rtm/RTC/util/ValueHolder.java",
                  standIns + "/VectorHolderCheck.java"},
                 classes.path(), &output),
             qPrintable(output));
    QVERIFY2(run(java, {"-cp", classes.path(), "VectorHolderCheck"}, classes.path(), &output),
             qPrintable(output));
    // A bad item leaves the parameter as it was, as OpenRTM keeps a value it cannot convert.
    QCOMPARE(output.trimmed().split(QLatin1Char('\n')),
             (QStringList {"3:0.5,1.5,2.0|second|0", "refused, kept 0.5,1.5,2.0"}));
}

void TestCodegenGolden::vectorConvertOnlyWithVectorParameters_data()
{
    addFixtureRows();
}

// VectorConvert.h is written, and included by the component header, exactly when a
// configuration parameter is a vector (of the fixtures, ConfigComp's `order` and `weights`).
void TestCodegenGolden::vectorConvertOnlyWithVectorParameters()
{
    QFETCH(QString, fixture);
    const bool vectors = fixture == QLatin1String("ConfigComp");
    const QDir project(projectDir(fixture));
    const QString header = QStringLiteral("include/%1/VectorConvert.h").arg(fixture);
    QCOMPARE(QFileInfo::exists(project.filePath(header)), vectors);
    QFile component(project.filePath(QStringLiteral("include/%1/%1.h").arg(fixture)));
    QVERIFY(component.open(QIODevice::ReadOnly));
    const QByteArray text = component.readAll();
    QCOMPARE(text.contains("#include \"VectorConvert.h\""), vectors);
    if (vectors) // before OpenRTM's headers, whose conversion templates must see it
        QVERIFY(text.indexOf("VectorConvert.h") < text.indexOf("#include <rtm/"));
}

// The generated VectorConvert.h compiled as C++11 into a program that reads vectors of
// double, int and string the way OpenRTM-aist's configuration does (through a template like
// coil::stringTo, defined after the header), and run.
void TestCodegenGolden::cppVectorConvertReadsVectors()
{
    QString compiler = QStandardPaths::findExecutable(QStringLiteral("g++"));
    if (compiler.isEmpty())
        compiler = QStandardPaths::findExecutable(QStringLiteral("c++"));
    // The project builds with a C++ compiler, so one is always there: its absence is a failure.
    QVERIFY2(!compiler.isEmpty(), "no C++ compiler on PATH to compile VectorConvert.h");
    const QString include
        = QDir(projectDir(QStringLiteral("ConfigComp"))).filePath("include/ConfigComp");
    QVERIFY(QFileInfo::exists(include + QStringLiteral("/VectorConvert.h")));
    QTemporaryDir work;
    QFile source(work.filePath(QStringLiteral("readvectors.cpp")));
    QVERIFY(source.open(QIODevice::WriteOnly));
    source.write(R"(#include "VectorConvert.h"
#include <iostream>

namespace coil {
template <typename To> bool stringTo(To& value, const char* text)
{
  std::istringstream in(text);
  return !(in >> value).fail();
}
}

template <typename T> void show(const char* text)
{
  std::vector<T> values;
  std::istringstream in(text);
  in >> values;
  std::cout << (in.fail() ? "fail" : "ok") << ' ' << values.size();
  for (typename std::vector<T>::size_type i = 0; i < values.size(); ++i)
    std::cout << '|' << values[i];
  std::cout << '\n';
}

int main()
{
  show<double>("-1.57,1.57");
  show<double>(" 0.5 , 2 ");
  show<int>("1, 2 ,3");
  show<std::string>("first, second item ,third");
  show<std::string>("alone");
  show<int>("  ");
  show<int>("1,x,3");
  show<double>("1.5,");
  std::vector<int> kept(1, 7);
  std::istringstream bad("4,five");
  bad >> kept;
  std::cout << "kept " << kept.size() << '|' << kept[0] << '\n';
  std::vector<double> bound;
  std::cout << "stringTo " << coil::stringTo(bound, "-1.57,1.57") << ' ' << bound.size() << '\n';
  return 0;
}
)");
    source.close();
    QString output;
    const QString program = work.filePath(QStringLiteral("readvectors"));
    QVERIFY2(run(compiler,
                 {"-std=c++11", "-Wall", "-Wextra", "-pedantic", "-Werror", "-I" + include,
                  source.fileName(), "-o", program},
                 work.path(), &output),
             qPrintable(output));
    QVERIFY2(run(program, {}, work.path(), &output), qPrintable(output));
    QCOMPARE(
        output.split(QLatin1Char('\n'), Qt::SkipEmptyParts),
        (QStringList {"ok 2|-1.57|1.57", "ok 2|0.5|2", "ok 3|1|2|3", "ok 3|first|second item|third",
                      "ok 1|alone", "ok 0", "fail 0", "fail 0", "kept 1|7", "stringTo 1 2"}));
}

QTEST_GUILESS_MAIN(TestCodegenGolden)
#include "tst_codegengolden.moc"
