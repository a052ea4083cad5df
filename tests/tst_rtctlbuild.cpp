// SPDX-License-Identifier: MIT
// `rtctl build DIR` as a user or a script runs it, on the tiny fixture projects of
// tests/data/projectbuild/.
#include "rtctlrunner.h"
#include "tst_builderbuildsupport.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class TestRtctlBuild : public QObject
{
    Q_OBJECT

private slots:
    void usageErrors_data();
    void usageErrors();
    void buildsProject();
    void listsCompileErrors();
    void folderWithoutProjectFails();
    void interruptCancelsBuild();
};

void TestRtctlBuild::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("no folder") << QStringList {"build"};
    QTest::newRow("two folders") << QStringList {"build", "a", "b"};
    QTest::newRow("bad config") << QStringList {"build", "a", "--config", "Fast"};
    QTest::newRow("prefix without value") << QStringList {"build", "a", "--prefix"};
    QTest::newRow("bad jobs") << QStringList {"build", "a", "-j", "0"};
    QTest::newRow("unknown option") << QStringList {"build", "a", "--frob"};
}

void TestRtctlBuild::usageErrors()
{
    QFETCH(QStringList, arguments);
    const RtctlResult result = runRtctl(arguments);
    QCOMPARE(result.code, 2);
    QVERIFY2(result.err.contains(QStringLiteral("Usage:")), qPrintable(result.err));
}

void TestRtctlBuild::buildsProject()
{
    QTemporaryDir dir;
    QVERIFY(BuildFixture::copy(QStringLiteral("ok"), dir.path()));
    const RtctlResult result = runRtctl(
        {"build", dir.path(), "--config", "Debug", "--prefix", dir.path(), "-j", "2", "--clean"});
    QVERIFY2(result.code == 0, qPrintable(result.out + result.err));
    QVERIFY(result.out.contains(QStringLiteral("-DCMAKE_BUILD_TYPE=Debug")));
    QVERIFY(result.out.contains(QStringLiteral("-DCMAKE_PREFIX_PATH=") + dir.path()));
    QVERIFY(result.out.contains(QStringLiteral("--clean-first")));
    // The last line says what was built, naming the folder.
    QVERIFY2(result.lines().last().contains(dir.path()), qPrintable(result.out));
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("build/hello"))).isExecutable());
    QVERIFY2(result.err.isEmpty(), qPrintable(result.err));
}

void TestRtctlBuild::listsCompileErrors()
{
    QTemporaryDir dir;
    QVERIFY(BuildFixture::copy(QStringLiteral("broken"), dir.path()));
    const RtctlResult result = runRtctl({"build", dir.path(), "-j", "2"});
    QCOMPARE(result.code, 1);
    const QStringList problems = result.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const QString source = dir.filePath(QStringLiteral("src/broken.cpp"));
    QVERIFY2(problems.filter(QRegularExpression(QStringLiteral("^%1:6:\\d+: error: ")
                                                    .arg(QRegularExpression::escape(source))))
                     .size()
                 == 1,
             qPrintable(result.err));
    QVERIFY2(problems.last().startsWith(QStringLiteral("rtctl build: ")), qPrintable(result.err));
    QVERIFY(problems.last().contains(dir.path()));
}

void TestRtctlBuild::folderWithoutProjectFails()
{
    QTemporaryDir dir;
    const RtctlResult result = runRtctl({"build", dir.path()});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains(dir.path() + QStringLiteral(" has no CMakeLists.txt")),
             qPrintable(result.err));
}

// Ctrl+C (here SIGINT, as the terminal sends it to rtctl) stops the build it started too: the
// build runs in a process group of its own, out of the terminal's reach.
void TestRtctlBuild::interruptCancelsBuild()
{
    QTemporaryDir dir;
    QVERIFY(BuildFixture::copy(QStringLiteral("slow"), dir.path()));
    QProcess rtctl;
    rtctl.start(RTCTL_PATH, {"build", dir.path(), "-j", "2"});
    QVERIFY(rtctl.waitForStarted());
    const QString pidFile = dir.filePath(QStringLiteral("build/waiting.pid"));
    qint64 pid = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            QFile file(pidFile);
            pid = file.open(QIODevice::ReadOnly) ? file.readAll().trimmed().toLongLong() : 0;
            return pid > 0;
        }(),
        120000);
    QVERIFY(BuildFixture::processRuns(pid));
    ::kill(pid_t(rtctl.processId()), SIGINT);
    const bool ended = rtctl.waitForFinished(10000);
    if (!ended) {
        rtctl.kill();
        rtctl.waitForFinished();
    }
    QVERIFY(ended);
    QCOMPARE(rtctl.exitStatus(), QProcess::NormalExit);
    QCOMPARE(rtctl.exitCode(), 1);
    const QString err = QString::fromUtf8(rtctl.readAllStandardError());
    QVERIFY2(err.contains(QStringLiteral("cancelled")) && err.contains(dir.path()),
             qPrintable(err));
    QTRY_VERIFY_WITH_TIMEOUT(!BuildFixture::processRuns(pid), 5000);
}

QTEST_GUILESS_MAIN(TestRtctlBuild)
#include "tst_rtctlbuild.moc"
