// SPDX-License-Identifier: MIT
// The Port Monitor against a live rtmanager: samples of OutPorts in a table and a plot, pause,
// CSV export, removal of its connectors, the online diagram's Monitor Port, and a GUI thread that
// never waits for the ports.

#include "componentproxy.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "onlinediagram.h"
#include "onlinesession.h"
#include "portmonitor.h"
#include "rtpath.h"
#include "stallmeter.h"

#include <QChart>
#include <QFile>
#include <QLineSeries>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

#include <cmath>

using namespace SystemEditor;

class TestPortMonitor : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void showsSamplesOfSeveralPorts();
    void pauseExportAndRemove();
    void rateLimitsKeptSamples();
    void refusedPortsAreReported();
    void onlineDiagramAsksForAPort();

private:
    Corba::ComponentProxy component(const QString &instance) const;
    int connectors(const QString &instance, const QString &port) const
    {
        return int(component(instance).port(port).connectors.size());
    }

    LiveTest::LiveSystem m_live;
};

Corba::ComponentProxy TestPortMonitor::component(const QString &instance) const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/mon.host_cxt/%2.rtc").arg(m_live.namingServer(), instance));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestPortMonitor::initTestCase()
{
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    QVERIFY2(m_live.startHostManager(RTMANAGER_PATH, LiveTest::freePort(),
                                     QStringLiteral("mon"),
                                     {"manager.components.precreate=SeqOut?exec_cxt.periodic.rate=200"},
                                     &error),
             qPrintable(error));
    component("SeqOut0").activate(0);
}

void TestPortMonitor::showsSamplesOfSeveralPorts()
{
    PortMonitor monitor;
    monitor.resize(900, 300);
    monitor.show();
    const LiveTest::StallMeter stalls;
    const Corba::ComponentProxy seqOut = component("SeqOut0");
    monitor.watch(seqOut.path(), seqOut.port("Long"));
    monitor.watch(seqOut.path(), seqOut.port("DoubleSeq"));
    monitor.watch(seqOut.path(), seqOut.port("Long")); // already watched: only selected
    const QString longKey = seqOut.path() + ":Long";
    const QString seqKey = seqOut.path() + ":DoubleSeq";
    QCOMPARE(monitor.watched(), QStringList({longKey, seqKey}));
    QCOMPARE(monitor.current(), longKey);

    QTRY_VERIFY_WITH_TIMEOUT(monitor.samples(longKey).size() >= 5 && monitor.samples(seqKey).size() >= 5, 10000);
    QCOMPARE(connectors("SeqOut0", "Long"), 1);
    QCOMPARE(monitor.fields(longKey), QStringList({"data"}));
    QCOMPARE(monitor.fields(seqKey).size(), 10);
    QCOMPARE(monitor.fields(seqKey).first(), QString("data[0]"));
    // Values count up as SeqOut writes them.
    const QList<MonitorSample> samples = monitor.samples(longKey);
    QVERIFY(samples.last().value["data"].toInteger() > samples.first().value["data"].toInteger());

    QTRY_VERIFY_WITH_TIMEOUT(monitor.table()->rowCount() >= 5, 5000);
    QVERIFY2(monitor.table()->item(0, 1)->text().contains("data="), qPrintable(monitor.table()->item(0, 1)->text()));
    QCOMPARE(monitor.chart()->series().size(), 1);
    QTRY_VERIFY(static_cast<QLineSeries *>(monitor.chart()->series().first())->count() >= 5);

    // The value axis holds every point, ticks at round values: a 1, 2 or 5 times a power of ten
    // apart.
    const auto *axis = qobject_cast<QValueAxis *>(monitor.chart()->axes(Qt::Vertical).value(0));
    QVERIFY(axis);
    for (const QPointF &point :
         static_cast<QLineSeries *>(monitor.chart()->series().first())->points())
        QVERIFY2(point.y() >= axis->min() && point.y() <= axis->max(),
                 qPrintable(QString::number(point.y())));
    QVERIFY(axis->tickCount() >= 2);
    const double interval = (axis->max() - axis->min()) / (axis->tickCount() - 1);
    const double mantissa = interval / std::pow(10.0, std::floor(std::log10(interval)));
    QVERIFY2(qFuzzyCompare(mantissa, 1.0) || qFuzzyCompare(mantissa, 2.0)
                 || qFuzzyCompare(mantissa, 5.0),
             qPrintable(QString::number(interval)));
    const double steps = axis->min() / interval;
    QVERIFY2(qAbs(steps - std::round(steps)) < 1e-6, qPrintable(QString::number(axis->min())));
    // Labels carry the decimals the step needs, no more (2000, not 2000.0; 0.05, not 0.1).
    QCOMPARE(axis->labelFormat(),
             QStringLiteral("%.%1f").arg(std::max(0, int(-std::floor(std::log10(interval))))));

    monitor.setCurrent(seqKey);
    QTRY_COMPARE(monitor.chart()->series().size(), 10);
    if (qEnvironmentVariableIsSet("RTSTUDIO_PORTMONITOR_SCREENSHOT")) {
        QTest::qWait(1500);
        monitor.grab().save(qEnvironmentVariable("RTSTUDIO_PORTMONITOR_SCREENSHOT"));
    }
    QVERIFY2(stalls.worstMs() < 100, qPrintable(QString::number(stalls.worstMs())));
}

void TestPortMonitor::pauseExportAndRemove()
{
    auto monitor = std::make_unique<PortMonitor>();
    monitor->show();
    const Corba::ComponentProxy seqOut = component("SeqOut0");
    monitor->watch(seqOut.path(), seqOut.port("Short"));
    const QString key = seqOut.path() + ":Short";
    QTRY_VERIFY_WITH_TIMEOUT(monitor->table()->rowCount() >= 3, 10000);

    monitor->setPaused(true);
    QTest::qWait(150); // a refresh that may have been under way
    const QString newest = monitor->table()->item(0, 1)->text();
    const qsizetype kept = monitor->samples(key).size();
    QTRY_VERIFY(monitor->samples(key).size() > kept); // samples keep arriving…
    QCOMPARE(monitor->table()->item(0, 1)->text(), newest); // …the view stands still
    monitor->setPaused(false);
    QTRY_VERIFY(monitor->table()->item(0, 1)->text() != newest);

    QTemporaryDir dir;
    QString error;
    const QString csv = dir.filePath("short.csv");
    QVERIFY2(monitor->exportCsv(key, csv, &error), qPrintable(error));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.first(), QString("time,data"));
    QVERIFY(lines.size() > 3);
    QVERIFY2(QRegularExpression("^\\d+\\.\\d{3},-?\\d+$").match(lines.at(1)).hasMatch(), qPrintable(lines.at(1)));
    QVERIFY(!monitor->exportCsv(key, "/nonexistent/folder/x.csv", &error));
    QVERIFY2(error.contains("/nonexistent/folder/x.csv"), qPrintable(error));

    QCOMPARE(connectors("SeqOut0", "Short"), 1);
    monitor->unwatch(key);
    QVERIFY(monitor->watched().isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(connectors("SeqOut0", "Short"), 0, 10000);

    // Closing the monitor removes the connectors it still has.
    monitor->watch(seqOut.path(), seqOut.port("Float"));
    QTRY_COMPARE_WITH_TIMEOUT(connectors("SeqOut0", "Float"), 1, 10000);
    monitor.reset();
    QCOMPARE(connectors("SeqOut0", "Float"), 0);
}

void TestPortMonitor::rateLimitsKeptSamples()
{
    PortMonitor monitor;
    monitor.show();
    auto *rate = monitor.findChild<QSpinBox *>(QStringLiteral("portMonitorRate"));
    QVERIFY(rate);
    QCOMPARE(rate->value(), 0); // every sample by default
    monitor.setRate(5);
    const Corba::ComponentProxy seqOut = component("SeqOut0");
    monitor.watch(seqOut.path(), seqOut.port("Octet"));
    const QString key = seqOut.path() + ":Octet";
    // SeqOut writes 200 a second; five a second are kept, at least 200 ms apart.
    QTRY_VERIFY_WITH_TIMEOUT(monitor.samples(key).size() >= 4, 10000);
    const QList<MonitorSample> kept = monitor.samples(key);
    for (qsizetype i = 1; i < kept.size(); ++i)
        QVERIFY2(kept[i].receivedMs - kept[i - 1].receivedMs >= 200, qPrintable(QString::number(i)));
    QVERIFY2(monitor.received(key) > quint64(2 * kept.size()),
             qPrintable(QStringLiteral("%1 received, %2 kept").arg(monitor.received(key)).arg(kept.size())));
}

void TestPortMonitor::refusedPortsAreReported()
{
    PortMonitor monitor;
    QSignalSpy messages(&monitor, &PortMonitor::statusMessage);
    Corba::ComponentProxy seqOut = component("SeqOut0");
    Corba::PortInfo unknown = seqOut.port("Long");
    for (auto &[key, value] : unknown.properties) {
        if (key == "dataport.data_type")
            value = "IDL:Nowhere/Thing:1.0";
    }
    monitor.watch(seqOut.path(), unknown);
    const QString key = seqOut.path() + ":Long";
    QTRY_VERIFY(!monitor.problem(key).isEmpty());
    QVERIFY2(monitor.problem(key).contains("IDL:Nowhere/Thing:1.0"), qPrintable(monitor.problem(key)));
    QCOMPARE(connectors("SeqOut0", "Long"), 0);
    QVERIFY(!messages.isEmpty());

    // With the user's IDL folder the type is known; what remains is up to the port.
    QTemporaryDir idl;
    QFile file(idl.filePath("thing.idl"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("module Nowhere { struct Thing { long data; }; };\n");
    file.close();
    monitor.unwatch(key);
    monitor.setIdlDirectories({idl.path()});
    QSignalSpy started(&monitor, &PortMonitor::watchStarted);
    monitor.watch(seqOut.path(), unknown);
    QTRY_COMPARE_WITH_TIMEOUT(started.size(), 1, 10000);
    QVERIFY2(!started.first().at(1).toString().contains("IDL files"), qPrintable(started.first().at(1).toString()));
    monitor.unwatch(key);
    QTRY_COMPARE_WITH_TIMEOUT(connectors("SeqOut0", "Long"), 0, 10000);
}

void TestPortMonitor::onlineDiagramAsksForAPort()
{
    OnlineSession session;
    OnlineDiagram diagram(&session);
    const Corba::ComponentProxy seqOut = component("SeqOut0");
    QSignalSpy added(&diagram, &OnlineDiagram::componentAdded);
    diagram.addComponent(seqOut.path(), seqOut.ior(), {40, 40});
    QTRY_COMPARE_WITH_TIMEOUT(added.size(), 1, 10000);
    QStringList requested;
    connect(&session, &OnlineSession::portMonitorRequested, this,
            [&requested](const QString &path, const Corba::PortInfo &port) {
                requested.append(path + ':' + port.shortName());
            });
    diagram.monitorPort("SeqOut0", "Long");
    diagram.monitorPort("SeqOut0", "NoSuchPort");
    QCOMPARE(requested, QStringList({seqOut.path() + ":Long"}));
}

QTEST_MAIN(TestPortMonitor)
#include "tst_portmonitor.moc"
