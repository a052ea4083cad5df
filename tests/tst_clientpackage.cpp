// SPDX-License-Identifier: MIT
// The client library as other programs use it: the project installed into a temporary prefix, the
// example under share/rtstudio/examples/client configured with find_package(RTStudioClient) and
// built there, and run against a live name server and rtmanager: it restores and starts the
// bundled ConsoleInOut system.
#include "livesystem.h"

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class TestClientPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void headersKeepOmniOrbInside();
    void exampleRestoresAndStartsASystem();

private:
    static int run(const QString &program, const QStringList &arguments, QString *output);

    QTemporaryDir m_prefix;
    QTemporaryDir m_build;
};

int TestClientPackage::run(const QString &program, const QStringList &arguments, QString *output)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(300000)) {
        process.kill();
        process.waitForFinished();
        *output = QString::fromLocal8Bit(process.readAll());
        return -1;
    }
    *output = QString::fromLocal8Bit(process.readAll());
    return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
}

void TestClientPackage::initTestCase()
{
    QVERIFY(m_prefix.isValid() && m_build.isValid());
    QString output;
    QCOMPARE(run(CMAKE_COMMAND, {"--install", RTSTUDIO_BUILD_DIR, "--prefix", m_prefix.path()}, &output), 0);
    QVERIFY(QFile::exists(m_prefix.filePath("lib/cmake/RTStudioClient/RTStudioClientConfig.cmake")));
    QVERIFY(QFile::exists(m_prefix.filePath("include/rtstudio/restorer.h")));
    // Component packages and repositories (packages/) are part of the client library's API.
    QVERIFY(QFile::exists(m_prefix.filePath("include/rtstudio/repository.h")));
    QVERIFY(QFile::exists(m_prefix.filePath("include/rtstudio/componentpackager.h")));
}

void TestClientPackage::headersKeepOmniOrbInside()
{
    const QDir headers(m_prefix.filePath("include/rtstudio"));
    QStringList leaking;
    for (const QString &name : headers.entryList({"*.h"})) {
        QFile file(headers.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        for (const QByteArray &line : file.readAll().split('\n')) {
            if (line.startsWith("#include")
                && (line.contains("omniORB") || line.contains(".hh") || line.contains("yaml-cpp")))
                leaking.append(name + ": " + QString::fromUtf8(line));
        }
    }
    QVERIFY2(leaking.isEmpty(), qPrintable(leaking.join(' ')));
}

void TestClientPackage::exampleRestoresAndStartsASystem()
{
    QString output;
    const QString source = m_prefix.filePath("share/rtstudio/examples/client");
    QCOMPARE(run(CMAKE_COMMAND, {"-S", source, "-B", m_build.path(), "-DCMAKE_PREFIX_PATH=" + m_prefix.path()}, &output), 0);
    QVERIFY2(run(CMAKE_COMMAND, {"--build", m_build.path()}, &output) == 0, qPrintable(output));

    LiveTest::LiveSystem live;
    QString error;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    const quint16 managerPort = LiveTest::freePort();
    QVERIFY2(live.startHostManager(RTMANAGER_PATH, managerPort, "client", {}, &error), qPrintable(error));
    const QString system = m_prefix.filePath("share/rtstudio/examples/ConsoleInOut/ConsoleInOut.xml");
    const int code = run(m_build.filePath("runsystem"),
                         {live.namingServer(), QStringLiteral("corbaloc::127.0.0.1:%1").arg(managerPort), system},
                         &output);
    QVERIFY2(code == 0, qPrintable(output));
    QVERIFY2(output.contains("\nConsoleIn0 Active\n") && output.contains("\nConsoleOut0 Active\n"), qPrintable(output));

    // Usage and a file that is no system.
    QCOMPARE(run(m_build.filePath("runsystem"), {}, &output), 2);
    QCOMPARE(run(m_build.filePath("runsystem"), {live.namingServer(), "corbaloc::127.0.0.1:1", source + "/CMakeLists.txt"}, &output), 1);
    QVERIFY2(output.contains("CMakeLists.txt"), qPrintable(output));
}

QTEST_GUILESS_MAIN(TestClientPackage)
#include "tst_clientpackage.moc"
