// SPDX-License-Identifier: MIT
#include "codegenerator.h"
#include "idltypelibrary.h"
#include "profileio.h"
#include "projectwriter.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace Codegen;
using namespace Profile;

// The generated project of the fixture component, byte for byte, and checks with the real
// tools: Python's compiler, and omniidl + the C++ compiler for the servant code.
// Set RTSTUDIO_UPDATE_GOLDEN=1 to rewrite the golden files after an intended change.
class TestCodegenGolden : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesGoldenFiles();
    void deterministic();
    void pythonCompiles();
    void servantCompilesAgainstOmniidlStubs();

private:
    bool run(const QString &program, const QStringList &arguments, const QString &dir,
             QString *output);
    QList<GeneratedFile> m_files;
    QTemporaryDir m_project;
};

static QString data(const QString &relative)
{
    return QStringLiteral(RTSTUDIO_TEST_DATA_DIR "/codegen/") + relative;
}

static std::optional<QList<GeneratedFile>> generateFixture()
{
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(data("SampleComp.xml"), &diagnostics);
    if (!loaded || !loaded->rtc)
        return std::nullopt;
    IdlTypeLibrary library({QStringLiteral(RTSTUDIO_IDL_DIR), data("idl")});
    return CodeGenerator(*loaded->rtc, library.model())
        .generate({TargetLanguage::Cpp, TargetLanguage::Python, TargetLanguage::Java}, &diagnostics);
}

void TestCodegenGolden::initTestCase()
{
    const auto files = generateFixture();
    QVERIFY(files);
    m_files = *files;
    QVERIFY(m_project.isValid());
    Diagnostics diagnostics;
    QVERIFY(ProjectWriter(m_project.path()).write(m_files, &diagnostics));
}

void TestCodegenGolden::matchesGoldenFiles()
{
    const QDir golden(data("golden/SampleComp"));
    const bool update = qEnvironmentVariableIntValue("RTSTUDIO_UPDATE_GOLDEN") == 1;
    if (update)
        QVERIFY(ProjectWriter(golden.path()).write(m_files, nullptr) || true);
    QStringList generated;
    for (const GeneratedFile &file : std::as_const(m_files)) {
        generated << file.path;
        QFile expected(golden.filePath(file.path));
        if (update) {
            QDir().mkpath(QFileInfo(expected.fileName()).absolutePath());
            QVERIFY(expected.open(QIODevice::WriteOnly | QIODevice::Truncate));
            expected.write(file.content);
            continue;
        }
        QVERIFY2(expected.open(QIODevice::ReadOnly), qPrintable(file.path + " has no golden file"));
        const QList<QByteArray> want = expected.readAll().split('\n');
        const QList<QByteArray> got = file.content.split('\n');
        for (int i = 0; i < std::min(want.size(), got.size()); ++i)
            QVERIFY2(want.at(i) == got.at(i),
                     qPrintable(QStringLiteral("%1:%2: expected '%3', generated '%4'")
                                    .arg(file.path).arg(i + 1)
                                    .arg(QString::fromUtf8(want.at(i)), QString::fromUtf8(got.at(i)))));
        QCOMPARE(got.size(), want.size());
    }
    // No golden file may be left over from files the generator no longer writes.
    QStringList expectedFiles;
    QDirIterator it(golden.path(), QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        expectedFiles << golden.relativeFilePath(it.next());
    expectedFiles.sort();
    generated.sort();
    QCOMPARE(generated, expectedFiles);
    QVERIFY(generated.contains(QStringLiteral("include/SampleComp/SampleServiceSVC_impl.h")));
    QVERIFY(generated.contains(QStringLiteral("src/EchoSVC_impl.java")));
    QVERIFY(generated.contains(QStringLiteral("SampleService_idl_example.py")));
    QVERIFY(generated.contains(QStringLiteral("idl/SampleService.idl")));
}

void TestCodegenGolden::deterministic()
{
    const auto again = generateFixture();
    QVERIFY(again);
    QCOMPARE(*again, m_files);
}

bool TestCodegenGolden::run(const QString &program, const QStringList &arguments,
                            const QString &dir, QString *output)
{
    QProcess process;
    process.setWorkingDirectory(dir);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool finished = process.waitForFinished(120000);
    *output = QString::fromLocal8Bit(process.readAll());
    return finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

void TestCodegenGolden::pythonCompiles()
{
    const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
    if (python.isEmpty())
        QSKIP("python3 is not installed; the generated Python is not compiled");
    const QStringList scripts = QDir(m_project.path()).entryList({QStringLiteral("*.py")});
    QCOMPARE(scripts.size(), 2);
    for (const QString &script : scripts) {
        QString output;
        QVERIFY2(run(python, {"-m", "py_compile", script}, m_project.path(), &output),
                 qPrintable(script + ": " + output));
    }
}

void TestCodegenGolden::servantCompilesAgainstOmniidlStubs()
{
    const QString omniidl = QStandardPaths::findExecutable(QStringLiteral("omniidl"));
    const QString compiler = QStandardPaths::findExecutable(QStringLiteral("c++"));
    if (omniidl.isEmpty() || compiler.isEmpty())
        QSKIP("omniidl or c++ is not installed; the generated servants are not compiled");
    QTemporaryDir stubs;
    QString output;
    // The project's IDL copy plus the OpenRTM data types it includes, as the generated
    // idl/CMakeLists.txt compiles them.
    for (const QString &idl : {QDir(m_project.path()).filePath("idl/SampleService.idl"),
                               QStringLiteral(RTSTUDIO_IDL_DIR "/BasicDataType.idl")}) {
        QVERIFY2(run(omniidl, {"-bcxx", "-Wba", "-Wbh=.hh", "-Wbs=SK.cc", "-Wbd=DynSK.cc",
                               "-I" RTSTUDIO_IDL_DIR, idl},
                     stubs.path(), &output),
                 qPrintable(output));
    }
    // A translation unit that creates the servant: instantiating it fails to compile unless
    // every operation of the interface (and its bases) is implemented with the right signature.
    const QString driver = stubs.filePath("instantiate.cpp");
    QFile file(driver);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("#include \"SampleServiceSVC_impl.h\"\n"
               "int main() { EchoSVC_impl *servant = new EchoSVC_impl(); servant->_remove_ref(); }\n");
    file.close();
    const QString include = QDir(m_project.path()).filePath("include/SampleComp");
    for (const QString &source : {QDir(m_project.path()).filePath("src/SampleServiceSVC_impl.cpp"), driver}) {
        QVERIFY2(run(compiler, {"-std=c++11", "-fsyntax-only", "-Wall", "-Wextra",
                                "-Wno-unused-parameter", "-Werror", "-I" + stubs.path(),
                                "-I" + include, source},
                     stubs.path(), &output),
                 qPrintable(source + ":\n" + output));
    }
}

QTEST_GUILESS_MAIN(TestCodegenGolden)
#include "tst_codegengolden.moc"
