// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

// rtctl resurrect / start / stop / diff / cryo / teardown run as a user would, against omniNames
// and rtmanager, with the bundled ConsoleInOut example.
#include "livesystem.h"

#include <QTemporaryDir>
#include <QTest>

class TestDeployRtctl : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void wholeLifeCycle();
    void usageErrors_data();
    void usageErrors();
    void failedResurrectRollsBack();
    void cryoReportsTwoComponentsOfOneName();
    void startRunsWaitsSideBySide();

private:
    using Result = RtctlResult;
    Result rtctl(const QStringList &arguments);
    QString manager() const { return QStringLiteral("corbaloc::127.0.0.1:%1").arg(m_managerPort); }

    LiveTest::LiveSystem m_live;
    quint16 m_managerPort = 0;
    const QString m_example
        = RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml");
};

TestDeployRtctl::Result TestDeployRtctl::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments, {{QStringLiteral("RTCTREE_NAMESERVERS"), m_live.namingServer()}});
}

void TestDeployRtctl::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_managerPort = LiveTest::freePort();
    QVERIFY2(m_live.startProcess(RTMANAGER_PATH,
                                 {"-d", "-o",
                                  QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(m_managerPort),
                                  "-o", "corba.nameservers=" + m_live.namingServer(), "-o",
                                  "naming.formats=clihost.host_cxt/%n.rtc", "-o",
                                  "manager.naming_formats=clihost.host_cxt/%n.mgr"},
                                 "rtmanager ready", &error),
             qPrintable(error));
}

void TestDeployRtctl::wholeLifeCycle()
{
    const Result plan = rtctl({"resurrect", "--create", "--dry-run", "-m", manager(), m_example});
    QCOMPARE(plan.code, 0);
    QVERIFY2(plan.out.contains("component ConsoleIn0 create (ConsoleIn?instance_name=ConsoleIn0"),
             qPrintable(plan.out));
    const Result noCreate = rtctl({"resurrect", "--dry-run", m_example});
    QCOMPARE(noCreate.code, 1);
    QVERIFY(noCreate.out.contains("component ConsoleIn0 missing"));

    const Result created = rtctl({"resurrect", "--create", "-m", manager(), m_example});
    QVERIFY2(created.code == 0, qPrintable(created.out + created.err));
    // The step names the manager that created the component.
    QVERIFY2(created.lines().contains("done create ConsoleIn0: ConsoleIn?instance_name=ConsoleIn0"
                                      "&exec_cxt.periodic.rate=1000 by " + manager()),
             qPrintable(created.out));
    QVERIFY(created.out.contains("done connect 6aa42771-908e-5b82-99ff-f41ebf13c242"));
    QCOMPARE(rtctl({"diff", m_example}).code, 0);

    const Result started = rtctl({"start", m_example});
    QVERIFY2(started.code == 0, qPrintable(started.out + started.err));
    QCOMPARE(started.lines(),
             QStringList({"done activate ConsoleOut0.0", "done activate ConsoleIn0.0"}));
    const Result stopped = rtctl({"stop", m_example});
    QCOMPARE(stopped.lines(),
             QStringList({"done deactivate ConsoleIn0.0", "done deactivate ConsoleOut0.0"}));

    QTemporaryDir dir;
    const QString frozen = dir.filePath("frozen.rtsys.xml");
    const Result cryo = rtctl({"cryo", "-n", "Frozen", "-e", "Test", "-o", frozen});
    QVERIFY2(cryo.code == 0, qPrintable(cryo.err));
    QFile file(frozen);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray xml = file.readAll();
    QVERIFY(xml.contains("rts:id=\"RTSystem:Test:Frozen:1.0\""));
    QVERIFY(xml.contains("rts:connectorId=\"6aa42771-908e-5b82-99ff-f41ebf13c242\""));
    QVERIFY(!xml.contains("inport_ior"));
    QCOMPARE(rtctl({"diff", frozen}).code, 0);

    const Result teardown = rtctl({"teardown", m_example});
    QCOMPARE(teardown.code, 0);
    QCOMPARE(teardown.lines(),
             QStringList({"done disconnect 6aa42771-908e-5b82-99ff-f41ebf13c242"}));
    const Result drift = rtctl({"diff", m_example});
    QCOMPARE(drift.code, 1);
    QCOMPARE(drift.lines(),
             QStringList({"missing connector 6aa42771-908e-5b82-99ff-f41ebf13c242:"
                          " saved 'ConsoleIn0.out -> ConsoleOut0.in'"}));
    // Restoring again (without --create) finds the components and connects again.
    const Result again = rtctl({"resurrect", m_example});
    QVERIFY2(again.code == 0, qPrintable(again.out + again.err));
    QCOMPARE(rtctl({"diff", m_example}).code, 0);
    QCOMPARE(rtctl({"teardown", m_example}).code, 0);
}

void TestDeployRtctl::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no file") << QStringList {"resurrect"} << "expected one FILE";
    QTest::newRow("bad host manager")
        << QStringList {"start", "--host-manager", "nohost", "x.xml"} << "HOST=ADDRESS";
    QTest::newRow("dry run is resurrect's")
        << QStringList {"stop", "--dry-run", "x.xml"} << "unknown option --dry-run";
}

void TestDeployRtctl::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Result result = rtctl(arguments);
    QCOMPARE(result.code, 2);
    QVERIFY2(result.err.contains(message), qPrintable(result.err));
}

void TestDeployRtctl::failedResurrectRollsBack()
{
    const Result result = rtctl({"resurrect", "--create", "-m", manager(),
                                 RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/broken.xml")});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains("rtctl resurrect: connect conn-bad:"), qPrintable(result.err));
    // Each step undone is reported once, after what it undid.
    const QStringList lines = result.lines();
    QCOMPARE(lines.count("rolled back connect conn-good: undone"), 1);
    QCOMPARE(lines.count("rolled back create Src0: undone"), 1);
    const QString created
        = "done create Src0: ConsoleIn?instance_name=Src0&exec_cxt.periodic.rate=200 by "
        + manager();
    QVERIFY2(lines.contains(created), qPrintable(result.out));
    QVERIFY(lines.indexOf("rolled back create Src0: undone") > lines.indexOf(created));
    // The created components are gone again (their manager unbinds them as they exit).
    QTRY_VERIFY(rtctl({"resurrect", "--dry-run",
                       RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/broken.xml")})
                    .out.contains("component Src0 missing"));
}

// A saved system tells its components apart by instance name only: of two live components with
// one name (on two hosts here) cryo saves the first and says so instead of dropping one silently.
void TestDeployRtctl::cryoReportsTwoComponentsOfOneName()
{
    QString error;
    QVERIFY2(m_live.startHostManager(
                 RTMANAGER_PATH, LiveTest::freePort(), "twinhost",
                 {"manager.components.precreate=ConsoleIn?instance_name=Twin0"}, &error),
             qPrintable(error));
    QCOMPARE(rtctl({"mgr", manager(), "create", "ConsoleIn?instance_name=Twin0"}).code, 0);
    const QString first
        = QStringLiteral("/%1/clihost.host_cxt/Twin0.rtc").arg(m_live.namingServer());
    const QString second
        = QStringLiteral("/%1/twinhost.host_cxt/Twin0.rtc").arg(m_live.namingServer());
    QTemporaryDir dir;
    const QString file = dir.filePath("twins.rtsys.xml");
    const Result cryo = rtctl({"cryo", "-o", file, first, second});
    QCOMPARE(cryo.code, 1);
    QVERIFY2(cryo.err.contains(second + ": another component is named Twin0 too (" + first + ")"),
             qPrintable(cryo.err));
    QFile saved(file);
    QVERIFY(saved.open(QIODevice::ReadOnly));
    QCOMPARE(saved.readAll().count("<rts:Components "), 1);
    // The same component reached twice is no clash.
    QCOMPARE(rtctl({"cryo", "-o", file, first, first}).code, 0);
    QCOMPARE(rtctl({"mgr", manager(), "delete", "Twin0"}).code, 0);
}

// rtctl start/stop execute the plan as rtshell does: the component no target names first, then the
// targets as their waits (counted from the plan's start) run out: Fast0 (200 ms) before Slow0
// (600 ms) though it comes later in the sequence. A SYNC timeout cancels the plan and says why.
void TestDeployRtctl::startRunsWaitsSideBySide()
{
    const QString file = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/waits.xml");
    const Result created = rtctl({"resurrect", "--create", "-m", manager(), file});
    QVERIFY2(created.code == 0, qPrintable(created.out + created.err));
    const auto activations = [](const Result &result, const QString &action) {
        QStringList lines;
        for (const QString &line : result.lines()) {
            if (line.startsWith("done " + action + ' '))
                lines.append(line);
        }
        return lines;
    };
    const Result started = rtctl({"start", file});
    QVERIFY2(started.code == 0, qPrintable(started.out + started.err));
    QCOMPARE(
        activations(started, "activate"),
        QStringList({"done activate Free0.0", "done activate Fast0.0", "done activate Slow0.0"}));
    QVERIFY2(started.lines().contains("done wait Slow0: 600 ms from the start"),
             qPrintable(started.out));
    const Result stopped = rtctl({"stop", file});
    QVERIFY2(stopped.code == 0, qPrintable(stopped.out + stopped.err));
    QCOMPARE(activations(stopped, "deactivate"),
             QStringList({"done deactivate Free0.0", "done deactivate Slow0.0",
                          "done deactivate Fast0.0"}));

    const QString timeout = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/synctimeout.xml");
    QCOMPARE(rtctl({"resurrect", "--create", "-m", manager(), timeout}).code, 0);
    const Result cancelled = rtctl({"start", timeout});
    QCOMPARE(cancelled.code, 1);
    QVERIFY2(cancelled.err.contains("rtctl start: wait Mid0: Src0 did not activate within 200 ms"),
             qPrintable(cancelled.err));
    QCOMPARE(activations(cancelled, "activate"), QStringList({"done activate Sink0.0"}));
    QVERIFY2(cancelled.lines().contains("failed wait Src0: cancelled"), qPrintable(cancelled.out));

    for (const char *name : {"Slow0", "Fast0", "Free0", "Src0", "Mid0", "Sink0"})
        QCOMPARE(rtctl({"mgr", manager(), "delete", name}).code, 0);
}

QTEST_GUILESS_MAIN(TestDeployRtctl)
#include "tst_deployrtctl.moc"
