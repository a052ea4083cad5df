// SPDX-License-Identifier: MIT
// rtctl print and inject against OpenRTM-aist 2.x's own example components (SeqOut, ConsoleOut):
// the samples its OutPorts send are decoded, values written into its InPort arrive as written,
// and rtctl's connectors are gone afterwards; rtmanager's rtc.conf connects to them by naming
// address. Skipped without an OpenRTM-aist prefix.

#include "livesystem.h"
#include "rtctlrunner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>

namespace {

const QString openRtmPrefix = QStringLiteral(RTSTUDIO_OPENRTM_PREFIX);

} // namespace

class TestInteropData : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void printsOpenRtmSamples();
    void injectsIntoOpenRtmInPort();
    void rtmanagerPreconnectsToOpenRtm();

private:
    RtctlResult rtctl(const QStringList &arguments) { return runRtctlAt(m_context, arguments); }
    QProcess *startExample(const QString &name, QString *error);

    LiveTest::LiveSystem m_live;
    QString m_context;
    QProcess *m_consoleOut = nullptr;
};

QProcess *TestInteropData::startExample(const QString &name, QString *error)
{
    return m_live.startOpenRtmExample(openRtmPrefix, name, QStringLiteral("openrtm"), error);
}

void TestInteropData::initTestCase()
{
    if (openRtmPrefix.isEmpty())
        QSKIP("skipped: no OpenRTM-aist");
    LiveTest::useOpenRtm(openRtmPrefix);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    m_context = QStringLiteral("/%1/openrtm.host_cxt").arg(m_live.namingServer());
    QVERIFY2(startExample(QStringLiteral("SeqOutComp"), &error), qPrintable(error));
    m_consoleOut = startExample(QStringLiteral("ConsoleOutComp"), &error);
    QVERIFY2(m_consoleOut, qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(rtctl({"cat", "SeqOut0.rtc"}).code == 0
                                 && rtctl({"cat", "ConsoleOut0.rtc"}).code == 0,
                             30000);
    const RtctlResult activated = rtctl({"act", "SeqOut0.rtc", "ConsoleOut0.rtc"});
    QVERIFY2(activated.code == 0, qPrintable(activated.err));
}

void TestInteropData::printsOpenRtmSamples()
{
    const RtctlResult text = rtctl({"print", "-n", "2", "SeqOut0.rtc:Long"});
    QVERIFY2(text.code == 0, qPrintable(text.err));
    QCOMPARE(text.lines().size(), 2);
    for (const QString &line : text.lines())
        QVERIFY2(QRegularExpression(QStringLiteral("^\\[\\d+\\.\\d{9}\\] data=-?\\d+$")).match(line).hasMatch(),
                 qPrintable(line));

    const RtctlResult json = rtctl({"print", "-n", "1", "--json", "SeqOut0.rtc:DoubleSeq"});
    QVERIFY2(json.code == 0, qPrintable(json.err));
    const QJsonArray data = QJsonDocument::fromJson(json.out.toUtf8())["data"].toArray();
    QCOMPARE(data.size(), 10); // OpenRTM's SeqOut writes ten values per sequence
    QVERIFY(data.first().isDouble());
    QVERIFY(!rtctl({"cat", "-l", "SeqOut0.rtc:Long"}).out.contains("Connected to"));
}

void TestInteropData::injectsIntoOpenRtmInPort()
{
    const RtctlResult injected = rtctl({"inject", "ConsoleOut0.rtc:in", "4242", "-7"});
    QVERIFY2(injected.code == 0, qPrintable(injected.err));
    // OpenRTM's ConsoleOut prints what it reads.
    QByteArray output;
    QTRY_VERIFY_WITH_TIMEOUT((output += m_consoleOut->readAllStandardOutput(),
                              output.contains("Received: 4242") && output.contains("Received: -7")),
                             10000);
    QVERIFY(!rtctl({"cat", "-l", "ConsoleOut0.rtc:in"}).out.contains("Connected to"));
}

void TestInteropData::rtmanagerPreconnectsToOpenRtm()
{
    // rtc.conf's preconnect naming OpenRTM-aist's ConsoleOut by its naming address: rtmanager's
    // ConsoleIn, created and activated by rtc.conf too, sends it its count from 1.
    const QString entry
        = QStringLiteral("ConsoleIn0.out?port=rtcname://%1/openrtm.host_cxt/ConsoleOut0.in").arg(m_live.namingServer());
    QString error;
    QProcess *manager = m_live.startHostManager(
        RTMANAGER_PATH, LiveTest::freePort(), QStringLiteral("ours"),
        {"manager.components.precreate=ConsoleIn", "manager.components.preconnect=" + entry,
         "manager.components.preactivation=ConsoleIn0"},
        &error);
    QVERIFY2(manager, qPrintable(error));
    QByteArray output;
    QTRY_VERIFY2_WITH_TIMEOUT((output += m_consoleOut->readAllStandardOutput(), output.contains("Received: 3\n")),
                              output.right(1000).constData(), 10000);
    const RtctlResult connected = rtctl({"cat", "-l", "ConsoleOut0.rtc:in"});
    QVERIFY2(connected.out.contains("Connected to"), qPrintable(connected.out));
    m_live.stop(manager);
}

QTEST_GUILESS_MAIN(TestInteropData)
#include "tst_interopdata.moc"
