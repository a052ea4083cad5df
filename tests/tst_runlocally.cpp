// SPDX-License-Identifier: MIT
// Online → Run System on Local Runtime, as the README's first command uses it: the bundled
// ConsoleInOut example restored onto a local runtime that RT Studio starts, its components active
// on an online diagram, ConsoleIn's samples in the Port Monitor, and the runtime stopped on quit
// (also when the program is told to end by a signal) unless the user keeps it.

#include "document.h"
#include "documentcontroller.h"
#include "localruntime.h"
#include "mainwindow.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinediagram.h"
#include "onlinedocks.h"
#include "onlinedocument.h"
#include "portmonitor.h"
#include "rtsdocument.h"

#include <QAction>
#include <QLabel>
#include <QProcess>
#include <QScopeGuard>
#include <QSettings>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using namespace Studio;

class TestRunLocally : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void failedStartIsReported();
    void runsTheExampleAndStopsOnQuit();
    void keptRuntimeOutlivesTheWindow();
    void terminationSignalStopsTheRuntime();
    void quitWhileStartingStopsTheRuntime();

private:
    OnlineDocument *onlineDiagram(MainWindow &window) const;

    QTemporaryDir m_runtime;
    QTemporaryDir m_settings;
};

void TestRunLocally::initTestCase()
{
    QVERIFY(m_runtime.isValid() && m_settings.isValid());
    QFile::setPermissions(m_runtime.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", m_runtime.path().toLocal8Bit());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_runlocally"));
    QVERIFY(Deploy::LocalRuntime::defaultFolder().startsWith(m_runtime.path()));
}

void TestRunLocally::cleanupTestCase()
{
    Deploy::LocalRuntime().stop(nullptr);
}

OnlineDocument *TestRunLocally::onlineDiagram(MainWindow &window) const
{
    for (Document *document : window.documents()->documents()) {
        if (auto *online = qobject_cast<OnlineDocument *>(document))
            return online;
    }
    return nullptr;
}

void TestRunLocally::failedStartIsReported()
{
    // No name server program to be found: the runtime cannot start, and Run says why.
    QTemporaryDir emptyPath;
    QVERIFY(emptyPath.isValid());
    const QByteArray path = qgetenv("PATH");
    const auto restorePath = qScopeGuard([&path] { qputenv("PATH", path); });
    qputenv("PATH", emptyPath.path().toLocal8Bit());
    auto window = std::make_unique<MainWindow>();
    QVERIFY(window->openFiles({RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml")}));
    auto *system = qobject_cast<RtsDocument *>(window->activeDocument());
    QVERIFY(system);
    QStringList messages;
    connect(window->onlineDocks(), &OnlineDocks::statusMessage, this,
            [&messages](const QString &message) { messages << message; });
    bool finished = false;
    QString error;
    window->onlineDocks()->runLocally(system->profile(), [&](const QString &e) {
        finished = true;
        error = e;
    });
    QTRY_VERIFY2_WITH_TIMEOUT(finished, qPrintable(messages.join(" | ")), 30000);
    QVERIFY2(error.contains("omniNames is not installed"), qPrintable(error));
    QVERIFY2(messages.last().startsWith("The local runtime did not start: "), qPrintable(messages.join(" | ")));
    QVERIFY(!window->onlineDocks()->localRuntime().running());
    auto *label = window->findChild<QLabel *>(QStringLiteral("localRuntimeStatus"));
    QVERIFY(label);
    // The status bar's message goes after a while; the label keeps saying so, the reason in its tooltip.
    QVERIFY2(label->text().contains("did not start"), qPrintable(label->text()));
    QVERIFY2(label->toolTip().contains("omniNames is not installed"), qPrintable(label->toolTip()));
}

void TestRunLocally::runsTheExampleAndStopsOnQuit()
{
    QSettings().clear();
    auto window = std::make_unique<MainWindow>();
    window->show();
    QVERIFY(window->openFiles({RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml")}));
    auto *system = qobject_cast<RtsDocument *>(window->activeDocument());
    QVERIFY(system);
    auto *label = window->findChild<QLabel *>(QStringLiteral("localRuntimeStatus"));
    QVERIFY(label);
    QVERIFY2(label->text().contains("stopped"), qPrintable(label->text()));

    bool finished = false;
    QString error;
    QStringList messages; // what the status bar said, for a report when it never finishes
    connect(window->onlineDocks(), &OnlineDocks::statusMessage, this,
            [&messages](const QString &message) { messages << message; });
    window->onlineDocks()->runLocally(system->profile(), [&](const QString &e) {
        finished = true;
        error = e;
    });
    QTRY_VERIFY2_WITH_TIMEOUT(finished, qPrintable(messages.join(" | ")), 60000);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const Deploy::LocalRuntimeState runtime = window->onlineDocks()->localRuntime();
    QVERIFY(runtime.running() && runtime.startedNow);
    QVERIFY2(label->text().contains(runtime.nameServerAddress()), qPrintable(label->text()));

    OnlineDocument *online = onlineDiagram(*window);
    QVERIFY(online && online->diagram());
    QTRY_COMPARE_WITH_TIMEOUT(int(online->diagram()->state("ConsoleIn0")), int(Corba::LifeCycleState::Active), 20000);
    QTRY_COMPARE_WITH_TIMEOUT(int(online->diagram()->state("ConsoleOut0")), int(Corba::LifeCycleState::Active), 20000);
    SystemEditor::PortMonitor *monitor = window->onlineDocks()->portMonitor();
    QTRY_COMPARE_WITH_TIMEOUT(monitor->watched().size(), 1, 20000);
    QVERIFY2(monitor->watched().first().endsWith("ConsoleIn0.rtc:out"), qPrintable(monitor->watched().first()));
    QTRY_VERIFY_WITH_TIMEOUT(monitor->samples(monitor->watched().first()).size() > 10, 20000);
    // The Name Service view shows the components the system put into the name server.
    const SystemEditor::NameServiceModel *names = window->onlineDocks()->nameService()->model();
    const QString component = QStringLiteral("/%1/%2.host_cxt/ConsoleIn0.rtc")
                                  .arg(runtime.nameServerAddress(), QSysInfo::machineHostName());
    QTRY_VERIFY2_WITH_TIMEOUT(names->indexOfPath(component).isValid(), qPrintable(component), 20000);

    // Quitting stops what this window started.
    window->close();
    window.reset();
    QVERIFY(!Deploy::LocalRuntime().status().nameServer.running);
    QVERIFY(!Deploy::LocalRuntime().status().manager.running);
}

void TestRunLocally::keptRuntimeOutlivesTheWindow()
{
    QSettings().clear();
    auto window = std::make_unique<MainWindow>();
    window->show();
    window->findChild<QAction *>(QStringLiteral("actionKeepLocalRuntime"))->setChecked(true);
    window->findChild<QAction *>(QStringLiteral("actionStartLocalRuntime"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(window->onlineDocks()->localRuntime().running(), 30000);
    const qint64 pid = window->onlineDocks()->localRuntime().manager.pid;
    window->close();
    window.reset();
    QVERIFY(Deploy::LocalRuntime().status().running());

    // A second window finds it running and does not stop it on quit either.
    window = std::make_unique<MainWindow>();
    QVERIFY(window->onlineDocks()->localRuntime().running());
    window->findChild<QAction *>(QStringLiteral("actionKeepLocalRuntime"))->setChecked(false);
    window->findChild<QAction *>(QStringLiteral("actionStartLocalRuntime"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(window->onlineDocks()->localRuntime().manager.pid == pid
                                 && !window->onlineDocks()->localRuntime().startedNow,
                             30000);
    window->close();
    window.reset();
    QVERIFY(Deploy::LocalRuntime().status().running());

    // Online → Stop Local Runtime.
    window = std::make_unique<MainWindow>();
    window->findChild<QAction *>(QStringLiteral("actionStopLocalRuntime"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!Deploy::LocalRuntime().status().nameServer.running, 20000);
    QVERIFY(!Deploy::LocalRuntime().status().manager.running);
    QTRY_VERIFY(window->findChild<QLabel *>(QStringLiteral("localRuntimeStatus"))->text().contains("stopped"));
}

void TestRunLocally::terminationSignalStopsTheRuntime()
{
    // A session that ends sends SIGTERM: rtstudio closes as from its close button, and the runtime
    // it started for --run-locally stops with it instead of staying behind for the next start.
    QTemporaryDir home;
    QVERIFY(home.isValid());
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("HOME"), home.path());
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    QProcess studio;
    studio.setProcessEnvironment(environment);
    studio.setProcessChannelMode(QProcess::ForwardedChannels);
    studio.start(RTSTUDIO_PATH,
                 {QStringLiteral("--run-locally"),
                  RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml")});
    QVERIFY(studio.waitForStarted());
    const auto endStudio = qScopeGuard([&studio] {
        if (studio.state() != QProcess::NotRunning) {
            studio.kill();
            studio.waitForFinished();
        }
    });
    QTRY_VERIFY_WITH_TIMEOUT(Deploy::LocalRuntime().status().running(), 60000);

    ::kill(pid_t(studio.processId()), SIGTERM);
    QVERIFY(studio.waitForFinished(30000));
    QCOMPARE(studio.exitStatus(), QProcess::NormalExit);
    QCOMPARE(studio.exitCode(), 0);
    QVERIFY(!Deploy::LocalRuntime().status().nameServer.running);
    QVERIFY(!Deploy::LocalRuntime().status().manager.running);
}

void TestRunLocally::quitWhileStartingStopsTheRuntime()
{
    // Closed before the start it asked for has come back: the start still runs to its end, and
    // what it brought up is stopped then.
    QSettings().clear();
    QVERIFY(!Deploy::LocalRuntime().status().running());
    auto window = std::make_unique<MainWindow>();
    window->show();
    window->findChild<QAction *>(QStringLiteral("actionStartLocalRuntime"))->trigger();
    QVERIFY(!window->onlineDocks()->localRuntime().running()); // not back yet
    window->close();
    window.reset();
    QVERIFY(!Deploy::LocalRuntime().status().nameServer.running);
    QVERIFY(!Deploy::LocalRuntime().status().manager.running);
}

QTEST_MAIN(TestRunLocally)
#include "tst_runlocally.moc"
