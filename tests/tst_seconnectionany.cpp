// SPDX-License-Identifier: MIT
// The System Editor connects any OutPort to an InPort of data type "any" (an FSM component's
// EventInPort), in either pick order; other differing types stay refused.
#include "connectionrules.h"

#include <QTest>

using namespace SystemEditor;

namespace {

PortInfo dataPort(PortKind kind, const QString &type)
{
    PortInfo port;
    port.name = "p";
    port.kind = kind;
    port.dataType = type;
    port.described = true;
    return port;
}

const ConnectorEnd Source {"Source0", "Source0.out"};
const ConnectorEnd Fsm {"Fsm0", "Fsm0.event"};

} // namespace

class TestSeConnectionAny : public QObject
{
    Q_OBJECT

private slots:
    void anyTakesEveryType_data();
    void anyTakesEveryType();
};

void TestSeConnectionAny::anyTakesEveryType_data()
{
    QTest::addColumn<QString>("outType");
    QTest::addColumn<QString>("inType");
    QTest::addColumn<bool>("allowed");
    QTest::newRow("TimedLong to any") << "RTC::TimedLong" << "any" << true;
    QTest::newRow("repository id to Any") << "IDL:RTC/TimedDoubleSeq:1.0" << "Any" << true;
    QTest::newRow("types differ") << "RTC::TimedLong" << "RTC::TimedDouble" << false;
    QTest::newRow("anything is a type") << "RTC::TimedLong" << "anything" << false;
}

void TestSeConnectionAny::anyTakesEveryType()
{
    QFETCH(QString, outType);
    QFETCH(QString, inType);
    QFETCH(bool, allowed);
    const PortInfo out = dataPort(PortKind::DataOut, outType);
    const PortInfo in = dataPort(PortKind::DataIn, inType);
    for (bool outFirst : {true, false}) {
        const ConnectionCheck check = outFirst ? ConnectionRules::check(Source, out, Fsm, in)
                                               : ConnectionRules::check(Fsm, in, Source, out);
        QCOMPARE(bool(check), allowed);
        if (allowed) {
            QCOMPARE(check.source, Source);
            QCOMPARE(check.target, Fsm);
        } else {
            QVERIFY2(check.reason.contains(inType), qPrintable(check.reason));
        }
    }
}

QTEST_GUILESS_MAIN(TestSeConnectionAny)
#include "tst_seconnectionany.moc"
