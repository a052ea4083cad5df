// SPDX-License-Identifier: MIT
#include "connectionrules.h"

#include <QTest>

using namespace Profile;
using namespace SystemEditor;

namespace {

PortInfo dataPort(PortKind kind, const QString &type)
{
    PortInfo port;
    port.name = "p";
    port.kind = kind;
    port.dataType = type;
    port.described = kind != PortKind::Unknown;
    return port;
}

PortInfo servicePort(const QList<InterfaceInfo> &interfaces)
{
    PortInfo port;
    port.name = "svc";
    port.kind = PortKind::Service;
    port.interfaces = interfaces;
    port.described = true;
    return port;
}

const InterfaceInfo Provided {"P", "Demo::Calc", "calc", RtcDirection::Provided};
const InterfaceInfo Required {"R", "Demo::Calc", "calc", RtcDirection::Required};
const InterfaceInfo RequiredOther {"R", "Demo::Calc", "other", RtcDirection::Required};
const InterfaceInfo RequiredOtherType {"R", "Demo::Other", "calc", RtcDirection::Required};

const ConnectorEnd A {"A0", "A0.p"};
const ConnectorEnd B {"B0", "B0.p"};

} // namespace

class TestSeConnectionRules : public QObject
{
    Q_OBJECT

private slots:
    void rules_data();
    void rules();
    void dataConnectionsAreOrderedOutToIn();
    void samePortsOfOneComponent();
    void checkThroughTheModel();
};

void TestSeConnectionRules::rules_data()
{
    QTest::addColumn<PortInfo>("first");
    QTest::addColumn<PortInfo>("second");
    QTest::addColumn<bool>("allowed");
    QTest::addColumn<QString>("reasonPart");
    const PortInfo outLong = dataPort(PortKind::DataOut, "RTC::TimedLong");
    const PortInfo inLong = dataPort(PortKind::DataIn, "RTC::TimedLong");
    const PortInfo inDouble = dataPort(PortKind::DataIn, "RTC::TimedDouble");
    const PortInfo unknown = dataPort(PortKind::Unknown, "");
    QTest::newRow("out-in same type") << outLong << inLong << true << "";
    QTest::newRow("in-out same type") << inLong << outLong << true << "";
    QTest::newRow("in-in") << inLong << inLong << false << "Two InPorts";
    QTest::newRow("out-out") << outLong << outLong << false << "Two OutPorts";
    QTest::newRow("types differ") << outLong << inDouble << false << "RTC::TimedDouble";
    QTest::newRow("unknown with out") << unknown << outLong << true << "";
    QTest::newRow("data with service") << outLong << servicePort({Provided}) << false
                                       << "service port";
    QTest::newRow("provided-required") << servicePort({Provided}) << servicePort({Required})
                                       << true << "";
    QTest::newRow("types differ but names pair")
        << servicePort({Provided}) << servicePort({RequiredOtherType}) << true << "";
    QTest::newRow("instance names differ")
        << servicePort({Provided}) << servicePort({RequiredOther}) << false << "No interface";
    QTest::newRow("same polarity") << servicePort({Required}) << servicePort({Required})
                                   << false << "No interface";
}

void TestSeConnectionRules::rules()
{
    QFETCH(PortInfo, first);
    QFETCH(PortInfo, second);
    QFETCH(bool, allowed);
    QFETCH(QString, reasonPart);
    const ConnectionCheck check = ConnectionRules::check(A, first, B, second);
    QCOMPARE(bool(check), allowed);
    if (allowed)
        QVERIFY(check.reason.isEmpty());
    else
        QVERIFY2(check.reason.contains(reasonPart), qPrintable(check.reason));
}

void TestSeConnectionRules::dataConnectionsAreOrderedOutToIn()
{
    const ConnectionCheck check =
        ConnectionRules::check(A, dataPort(PortKind::DataIn, "T"), B,
                               dataPort(PortKind::DataOut, "T"));
    QVERIFY(check);
    QCOMPARE(check.source, B);
    QCOMPARE(check.target, A);
    QCOMPARE(check.kind, ConnectorKind::Data);
    QCOMPARE(ConnectionRules::matchingInterfaces({Provided, Required}, {RequiredOther, Required}),
             (QList<QPair<int, int>> {{0, 1}}));
}

void TestSeConnectionRules::samePortsOfOneComponent()
{
    const ConnectionCheck check = ConnectionRules::check(
        A, dataPort(PortKind::DataOut, "T"), ConnectorEnd {"A0", "A0.q"},
        dataPort(PortKind::DataIn, "T"));
    QVERIFY(!check);
    QVERIFY(check.reason.contains("same component"));
}

void TestSeConnectionRules::checkThroughTheModel()
{
    RtcProfile out;
    RtcDataPort port;
    port.portType = "DataOutPort";
    port.name = "out";
    port.type = "RTC::TimedLong";
    out.dataPorts << port;
    RtcProfile in = out;
    in.dataPorts[0].portType = "DataInPort";
    in.dataPorts[0].name = "in";
    SystemModel model;
    RtsComponent a;
    a.instanceName = "A0";
    RtsComponent b;
    b.instanceName = "B0";
    model.addComponent(a, out);
    model.addComponent(b, in);
    const ConnectionCheck ok = ConnectionRules::check(model, {"B0", "B0.in"}, {"A0", "A0.out"});
    QVERIFY(ok);
    QCOMPARE(ok.source, (ConnectorEnd {"A0", "A0.out"}));
    const ConnectionCheck missing = ConnectionRules::check(model, {"B0", "B0.x"}, {"A0", "A0.out"});
    QVERIFY(!missing);
    QVERIFY(missing.reason.contains("B0.x"));
}

QTEST_GUILESS_MAIN(TestSeConnectionRules)
#include "tst_seconnectionrules.moc"
