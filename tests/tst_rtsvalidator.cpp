// SPDX-License-Identifier: MIT
#include "rtsvalidator.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTest>

using namespace Profile;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + name;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

QString joined(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

RtsProfile load(const QString &name)
{
    Diagnostics diagnostics;
    const QByteArray data = readFile(dataPath(name));
    const auto profile = name.endsWith(QLatin1String(".yaml"))
        ? readRtsYaml(data, name, &diagnostics)
        : readRtsXml(data, name, &diagnostics);
    if (!profile || !diagnostics.isEmpty())
        qWarning().noquote() << name << joined(diagnostics);
    return profile.value_or(RtsProfile());
}

RtsComponent component(const QString &instanceName, const QStringList &ports)
{
    RtsComponent c;
    c.id = QStringLiteral("RTC:V:c:%1:1.0").arg(instanceName);
    c.pathUri = instanceName;
    c.instanceName = instanceName;
    for (const QString &port : ports) {
        RtsPort p;
        p.name = port;
        c.dataPorts.append(p);
    }
    return c;
}

RtsDataPortConnector connector(const QString &id, const RtsComponent &from, const QString &fromPort,
                               const RtsComponent &to, const QString &toPort)
{
    RtsDataPortConnector c;
    c.connectorId = id;
    c.name = id;
    c.source.componentId = from.id;
    c.source.instanceName = from.instanceName;
    c.source.portName = fromPort;
    c.target.componentId = to.id;
    c.target.instanceName = to.instanceName;
    c.target.portName = toPort;
    return c;
}

} // namespace

class TestRtsValidator : public QObject
{
    Q_OBJECT

private slots:
    void acceptsSoundSystems_data();
    void acceptsSoundSystems();
    void reportsEachProblem_data();
    void reportsEachProblem();
    void reportsNothingElse();
    void checksPortsOnlyWhenListed();
    void locatesYamlProblems();
    void validatesLargeSystemsQuickly();
};

void TestRtsValidator::acceptsSoundSystems_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("full xml") << "rts/full.xml";
    QTest::newRow("full yaml") << "rts/full.yaml";
    QTest::newRow("legacy spellings") << "rts/legacy.xml";
    QTest::newRow("minimal") << "rts/minimal.xml";
}

void TestRtsValidator::acceptsSoundSystems()
{
    QFETCH(QString, name);
    const RtsProfile profile = load(name);
    QVERIFY(!profile.id.isEmpty());
    const Diagnostics diagnostics = validateRtsProfile(profile, name);
    QVERIFY2(diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
}

void TestRtsValidator::reportsEachProblem_data()
{
    QTest::addColumn<int>("line");
    QTest::addColumn<bool>("isError");
    QTest::addColumn<QString>("fragment");
    QTest::newRow("system id") << 3 << false << "does not have the form RTSystem:";
    QTest::newRow("duplicate instance") << 14 << true << "'A0' is used by more than one component";
    QTest::newRow("composite type") << 7 << false << "unknown composite type 'Sideways'";
    QTest::newRow("active set") << 7 << false << "active configuration set 'missing'";
    QTest::newRow("rate") << 11 << true << "rate 'fast' is not a number";
    QTest::newRow("location") << 12 << true << "x '1.5' is not a whole number";
    QTest::newRow("direction") << 12 << false << "direction 'NORTH'";
    QTest::newRow("component id") << 14 << false << "'A:B' does not have the form RTC:";
    QTest::newRow("boolean") << 14 << false << "isRequired 'maybe'";
    QTest::newRow("participant") << 18 << true << "'Z0' names no component";
    QTest::newRow("unknown port") << 23 << false << "has no port 'A0.nothing'";
    QTest::newRow("unknown component") << 24 << true << "'Nobody' names no component";
    QTest::newRow("push interval") << 21 << true << "push interval 'often'";
    QTest::newRow("policy typo") << 25 << false
                                 << "'overerite' (RT System Editor's typo) means 'overwrite'";
    QTest::newRow("duplicate connector")
        << 27 << true << "connector id 'dup' is used more than once";
    QTest::newRow("end id") << 29 << false << "'RTC:V:c:X:1.0' of 'B0' differs";
    QTest::newRow("sequence") << 32 << true << "sequence 'first'";
    QTest::newRow("execution context") << 33 << false << "no execution context '9'";
    QTest::newRow("wait time") << 34 << true << "wait time 'soon'";
    QTest::newRow("timeout") << 35 << true << "timeout '1.5'";
    QTest::newRow("sending timing") << 35 << false << "unknown sending timing 'LATER'";
    QTest::newRow("preceding component") << 36 << true << "'Ghost0' names no component";
    QTest::newRow("both conditions") << 32 << false << "both a wait time and preceding";
}

void TestRtsValidator::reportsEachProblem()
{
    QFETCH(int, line);
    QFETCH(bool, isError);
    QFETCH(QString, fragment);
    const QString name = QStringLiteral("rts/invalid.xml");
    const Diagnostics diagnostics = validateRtsProfile(load(name), name);
    const Diagnostic *found = nullptr;
    for (const Diagnostic &d : diagnostics) {
        if (d.message.contains(fragment))
            found = &d;
    }
    QVERIFY2(found, qPrintable(joined(diagnostics)));
    QCOMPARE(found->file, name);
    QCOMPARE(found->line, line);
    QVERIFY(found->column > 0);
    QCOMPARE(found->severity,
             isError ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning);
    QVERIFY(!found->object.isEmpty());
}

void TestRtsValidator::reportsNothingElse()
{
    const QString name = QStringLiteral("rts/invalid.xml");
    const Diagnostics diagnostics = validateRtsProfile(load(name), name);
    QCOMPARE(diagnostics.size(), 23); // the rows of reportsEachProblem_data()
}

void TestRtsValidator::checksPortsOnlyWhenListed()
{
    RtsProfile p
        = RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("N"), QStringLiteral("1"));
    const RtsComponent a = component(QStringLiteral("A0"), {QStringLiteral("A0.out")});
    const RtsComponent b = component(QStringLiteral("B0"), {}); // ports not listed
    p.components << a << b;
    p.dataPortConnectors << connector(QStringLiteral("c1"), a, QStringLiteral("A0.out"), b,
                                      QStringLiteral("B0.anything"));
    QVERIFY2(validateRtsProfile(p, QString()).isEmpty(),
             qPrintable(joined(validateRtsProfile(p, {}))));

    p.dataPortConnectors << connector(QStringLiteral("c2"), b, QStringLiteral("B0.x"), a,
                                      QStringLiteral("A0.in"));
    const Diagnostics diagnostics = validateRtsProfile(p, QStringLiteral("mem"));
    QCOMPARE(diagnostics.size(), 1);
    QVERIFY(diagnostics.at(0).message.contains(QStringLiteral("no port 'A0.in'")));
    QCOMPARE(diagnostics.at(0).line, 0); // built in memory: no position
    QCOMPARE(diagnostics.at(0).toString(),
             QStringLiteral("mem: warning: connector c2: component 'A0' has no port 'A0.in'"));

    p.components[1].instanceName.clear();
    QVERIFY(hasErrors(validateRtsProfile(p, QString())));
}

void TestRtsValidator::locatesYamlProblems()
{
    const QByteArray yaml = R"(rtsProfile:
    id: RTSystem:V:N:1
    version: '0.2'
    creationDate: 2024-01-01T00:00:00
    updateDate: 2024-01-01T00:00:00
    components:
        -   id: RTC:V:c:A:1.0
            pathUri: a
            instanceName: A0
            isRequired: true
            "rtsExt::location": {x: left, y: 0, height: -1, width: -1, direction: UP}
)";
    Diagnostics diagnostics;
    const auto profile = readRtsYaml(yaml, QStringLiteral("v.yaml"), &diagnostics);
    QVERIFY2(profile && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    const Diagnostics found = validateRtsProfile(*profile, QStringLiteral("v.yaml"));
    QCOMPARE(found.size(), 1);
    QCOMPARE(found.at(0).line, 11);
    QVERIFY(found.at(0).message.contains(QStringLiteral("x 'left'")));
}

void TestRtsValidator::validatesLargeSystemsQuickly()
{
    RtsProfile p
        = RtsProfile::createNew(QStringLiteral("V"), QStringLiteral("N"), QStringLiteral("1"));
    for (int i = 0; i < 1000; ++i) {
        const QString name = QStringLiteral("C%1").arg(i);
        p.components << component(name,
                                  {name + QStringLiteral(".in"), name + QStringLiteral(".out")});
    }
    for (int i = 0; i < 1500; ++i) {
        const RtsComponent &from = p.components.at(i % 1000);
        const RtsComponent &to = p.components.at((i * 7 + 3) % 1000);
        p.dataPortConnectors << connector(QStringLiteral("c%1").arg(i), from,
                                          from.instanceName + QStringLiteral(".out"), to,
                                          to.instanceName + QStringLiteral(".in"));
    }
    p.dataPortConnectors.last().connectorId = QStringLiteral("c0");
    QElapsedTimer timer;
    timer.start();
    const Diagnostics diagnostics = validateRtsProfile(p, QString());
    const qint64 ms = timer.elapsed();
    QCOMPARE(diagnostics.size(), 1);
    QVERIFY(diagnostics.at(0).message.contains(QStringLiteral("'c0' is used more than once")));
    qInfo("validated 1000 components and 1500 connectors in %lld ms", ms);
    QVERIFY2(ms < 500, "validation is far too slow (quadratic look-ups?)");
}

QTEST_GUILESS_MAIN(TestRtsValidator)
#include "tst_rtsvalidator.moc"
