// SPDX-License-Identifier: MIT
// Codegen::ProjectBuilder: the lines it understands, and real CMake builds of the tiny fixture
// projects under tests/data/projectbuild/ (one that builds, one with a compile error, one that
// does not configure, one whose build would run for minutes and is cancelled).
#include "projectbuilder.h"
#include "tst_builderbuildsupport.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace Codegen;
using Profile::Diagnostic;

class TestCodegenProjectBuilder : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void parsesProblemLines_data();
    void parsesProblemLines();
    void ignoresOtherLines_data();
    void ignoresOtherLines();
    void parsesProgress_data();
    void parsesProgress();
    void buildsProject();
    void listsCompileErrors();
    void listsCMakeErrors();
    void refusesFolderWithoutProject();
    void cancelStopsLongBuild();

private:
    /// Starts building the fixture `name` (copied into `dir`); false when it did not start.
    bool startBuild(ProjectBuilder *builder, const QString &name, const QTemporaryDir &dir);
};

namespace {

/// A whole configure + build of a tiny project; generous for a loaded machine.
constexpr int buildTimeoutMs = 120000;

} // namespace

void TestCodegenProjectBuilder::initTestCase()
{
    // The project itself is built with CMake and a C++ compiler, so both are there.
    QVERIFY(!QStandardPaths::findExecutable(QStringLiteral("cmake")).isEmpty());
}

void TestCodegenProjectBuilder::parsesProblemLines_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("lineNumber");
    QTest::addColumn<int>("column");
    QTest::addColumn<bool>("error");
    QTest::addColumn<QString>("message");
    QTest::newRow("gcc error") << "/p/src/a.cpp:12:5: error: 'x' was not declared in this scope"
                               << "/p/src/a.cpp" << 12 << 5 << true
                               << "'x' was not declared in this scope";
    QTest::newRow("gcc warning") << "/p/include/A/A.h:3:9: warning: unused variable 'y' [-Wunused]"
                                 << "/p/include/A/A.h" << 3 << 9 << false
                                 << "unused variable 'y' [-Wunused]";
    QTest::newRow("fatal error") << "/p/src/a.cpp:1:10: fatal error: rtm/Manager.h: No such file"
                                 << "/p/src/a.cpp" << 1 << 10 << true
                                 << "rtm/Manager.h: No such file";
    QTest::newRow("no column") << "/p/src/a.cpp:7: error: expected ';'"
                               << "/p/src/a.cpp" << 7 << 0 << true << "expected ';'";
    QTest::newRow("relative to the build folder") << "../src/b.cpp:4:2: error: bad"
                                                  << "/p/src/b.cpp" << 4 << 2 << true << "bad";
    QTest::newRow("colours") << "\x1b[01m\x1b[K/p/a.cpp:2:1:\x1b[m\x1b[K \x1b[01;31m\x1b[Kerror: "
                                "\x1b[m\x1b[Kboom"
                             << "/p/a.cpp" << 2 << 1 << true << "boom";
}

void TestCodegenProjectBuilder::parsesProblemLines()
{
    QFETCH(QString, line);
    QFETCH(QString, file);
    QFETCH(int, lineNumber);
    QFETCH(int, column);
    QFETCH(bool, error);
    QFETCH(QString, message);
    const std::optional<Diagnostic> found
        = ProjectBuilder::parseProblemLine(line, QStringLiteral("/p/build"));
    QVERIFY(found);
    QCOMPARE(found->file, file);
    QCOMPARE(found->line, lineNumber);
    QCOMPARE(found->column, column);
    QCOMPARE(found->severity == Diagnostic::Severity::Error, error);
    QCOMPARE(found->message, message);
}

void TestCodegenProjectBuilder::ignoresOtherLines_data()
{
    QTest::addColumn<QString>("line");
    QTest::newRow("note") << "/p/a.cpp:3:1: note: declared here";
    QTest::newRow("context") << "/p/a.cpp: In function 'int main()':";
    QTest::newRow("make") << "gmake[2]: *** [CMakeFiles/a.dir/build.make:76: a.o] Error 1";
    QTest::newRow("progress") << "[ 50%] Building CXX object CMakeFiles/a.dir/a.cpp.o";
    QTest::newRow("source line") << "    6 |     return undeclaredName;";
}

void TestCodegenProjectBuilder::ignoresOtherLines()
{
    QFETCH(QString, line);
    QVERIFY(!ProjectBuilder::parseProblemLine(line, QStringLiteral("/p/build")));
}

void TestCodegenProjectBuilder::parsesProgress_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("done");
    QTest::addColumn<int>("total");
    QTest::newRow("ninja") << "[3/10] Building CXX object src/CMakeFiles/A.dir/A.cpp.o" << 3 << 10;
    QTest::newRow("make") << "[ 42%] Building CXX object src/CMakeFiles/A.dir/A.cpp.o" << 42 << 100;
    QTest::newRow("make done") << "[100%] Built target A" << 100 << 100;
    QTest::newRow("none") << "-- Configuring done" << -1 << -1;
}

void TestCodegenProjectBuilder::parsesProgress()
{
    QFETCH(QString, line);
    QFETCH(int, done);
    QFETCH(int, total);
    const std::optional<BuildProgress> progress = ProjectBuilder::parseProgressLine(line);
    QCOMPARE(progress.has_value(), done >= 0);
    if (progress) {
        QCOMPARE(progress->done, done);
        QCOMPARE(progress->total, total);
    }
}

bool TestCodegenProjectBuilder::startBuild(ProjectBuilder *builder, const QString &name,
                                           const QTemporaryDir &dir)
{
    if (!dir.isValid() || !BuildFixture::copy(name, dir.path()))
        return false;
    BuildOptions options;
    options.projectDir = dir.path();
    options.jobs = 2;
    return builder->start(options);
}

void TestCodegenProjectBuilder::buildsProject()
{
    ProjectBuilder builder;
    QSignalSpy finished(&builder, &ProjectBuilder::finished);
    QSignalSpy progress(&builder, &ProjectBuilder::progress);
    QStringList output;
    connect(&builder, &ProjectBuilder::output, this, [&](const QString &line) { output << line; });
    QTemporaryDir dir;
    QVERIFY(startBuild(&builder, QStringLiteral("ok"), dir));
    QVERIFY(builder.isRunning());
    QVERIFY(finished.wait(buildTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(output.join('\n')));
    const QString message = finished.at(0).at(1).toString();
    QVERIFY2(message.contains(QDir::toNativeSeparators(dir.path())), qPrintable(message));
    QVERIFY(!builder.isRunning());
    QVERIFY(builder.problems().isEmpty());
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("build/hello"))).isExecutable());
    // Both steps were run and printed, and the build step counted its progress.
    QVERIFY(output.join('\n').contains(QStringLiteral("-DCMAKE_BUILD_TYPE=Release")));
    QVERIFY(output.join('\n').contains(QStringLiteral("--build")));
    bool counted = false;
    for (const QList<QVariant> &step : std::as_const(progress))
        counted = counted || (step.at(1).toInt() > 0 && step.at(0).toInt() == step.at(1).toInt());
    QVERIFY(counted);
}

void TestCodegenProjectBuilder::listsCompileErrors()
{
    ProjectBuilder builder;
    QSignalSpy finished(&builder, &ProjectBuilder::finished);
    QSignalSpy problems(&builder, &ProjectBuilder::problem);
    QTemporaryDir dir;
    QVERIFY(startBuild(&builder, QStringLiteral("broken"), dir));
    QVERIFY(finished.wait(buildTimeoutMs));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    const QString message = finished.at(0).at(1).toString();
    QVERIFY2(message.contains(QDir::toNativeSeparators(dir.path())), qPrintable(message));
    QCOMPARE(problems.count(), builder.problems().size());
    const QString source = dir.filePath(QStringLiteral("src/broken.cpp"));
    bool error = false;
    bool warning = false;
    for (const Diagnostic &d : builder.problems()) {
        error = error
            || (d.severity == Diagnostic::Severity::Error && d.file == source && d.line == 6
                && d.column > 0 && d.message.contains(QStringLiteral("undeclaredName")));
        warning = warning
            || (d.severity == Diagnostic::Severity::Warning && d.file == source && d.line == 5);
    }
    QVERIFY(error);
    QVERIFY(warning);
}

void TestCodegenProjectBuilder::listsCMakeErrors()
{
    ProjectBuilder builder;
    QSignalSpy finished(&builder, &ProjectBuilder::finished);
    QTemporaryDir dir;
    QVERIFY(startBuild(&builder, QStringLiteral("cmakeerror"), dir));
    QVERIFY(finished.wait(buildTimeoutMs));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY(finished.at(0).at(1).toString().startsWith(QStringLiteral("Configuring")));
    QVERIFY(!builder.problems().isEmpty());
    const Diagnostic first = builder.problems().first();
    QCOMPARE(first.file, dir.filePath(QStringLiteral("CMakeLists.txt")));
    QCOMPARE(first.line, 5);
    QVERIFY2(first.message.contains(QStringLiteral("missing.cpp")), qPrintable(first.message));
    // The build step never ran.
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("build/nothing"))));
}

void TestCodegenProjectBuilder::refusesFolderWithoutProject()
{
    ProjectBuilder builder;
    QSignalSpy finished(&builder, &ProjectBuilder::finished);
    QTemporaryDir dir;
    BuildOptions options;
    options.projectDir = dir.path();
    QVERIFY(!builder.start(options));
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY(finished.at(0).at(1).toString().contains(QDir::toNativeSeparators(dir.path())));
    QCOMPARE(builder.problems().size(), 1);
    QVERIFY(!builder.isRunning());
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("build"))));
}

void TestCodegenProjectBuilder::cancelStopsLongBuild()
{
    ProjectBuilder builder;
    QSignalSpy finished(&builder, &ProjectBuilder::finished);
    QTemporaryDir dir;
    QVERIFY(startBuild(&builder, QStringLiteral("slow"), dir));
    // The fixture's waiting command writes its process id when it starts.
    const QString pidFile = dir.filePath(QStringLiteral("build/waiting.pid"));
    qint64 pid = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            QFile file(pidFile);
            pid = file.open(QIODevice::ReadOnly) ? file.readAll().trimmed().toLongLong() : 0;
            return pid > 0;
        }(),
        buildTimeoutMs);
    QVERIFY(finished.isEmpty());
    QVERIFY(BuildFixture::processRuns(pid));
    QElapsedTimer clock;
    clock.start();
    builder.cancel();
    QVERIFY(finished.count() == 1 || finished.wait(10000));
    QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY(finished.at(0).at(1).toString().contains(QStringLiteral("cancelled")));
    QVERIFY(builder.wasCancelled());
    QVERIFY(!builder.isRunning());
    // Not only cmake: the command it ran (below make and a shell) is gone too.
    QTRY_VERIFY_WITH_TIMEOUT(!BuildFixture::processRuns(pid), 5000);
}

QTEST_GUILESS_MAIN(TestCodegenProjectBuilder)
#include "tst_codegenprojectbuilder.moc"
