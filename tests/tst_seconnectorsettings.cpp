// SPDX-License-Identifier: MIT
#include "connectorsettings.h"

#include <QTest>

using namespace Profile;
using namespace SystemEditor;

class TestSeConnectorSettings : public QObject
{
    Q_OBJECT

private slots:
    void defaults();
    void enablingRules_data();
    void enablingRules();
    void applyWritesAttributesAndKeys();
    void disabledFieldsAreRemoved();
    void readBackIsTheSame();
    void freePropertiesKeepBendPoints();
    void validation_data();
    void validation();
};

void TestSeConnectorSettings::defaults()
{
    const ConnectorSettings s =
        ConnectorSettings::defaults("ConsoleIn0.out", "ConsoleOut0.in", "RTC::TimedLong");
    QCOMPARE(s.name, QStringLiteral("out_in"));
    QCOMPARE(s.interfaceType, QStringLiteral("corba_cdr"));
    QCOMPARE(s.dataflowType, QStringLiteral("push"));
    QCOMPARE(s.subscriptionType, QStringLiteral("flush"));
    QCOMPARE(s.pushRate, QStringLiteral("1000.0"));
    QVERIFY(s.validate().isEmpty());
    QVERIFY(ConnectorSettings::fullPolicies().contains("overwrite"));
    QVERIFY(!ConnectorSettings::fullPolicies().contains("overerite"));
}

void TestSeConnectorSettings::enablingRules_data()
{
    QTest::addColumn<QString>("dataflow");
    QTest::addColumn<QString>("subscription");
    QTest::addColumn<QString>("policy");
    QTest::addColumn<bool>("subscriptionOn");
    QTest::addColumn<bool>("rateOn");
    QTest::addColumn<bool>("policyOn");
    QTest::addColumn<bool>("skipOn");
    QTest::newRow("pull") << "pull" << "periodic" << "skip" << false << false << false << false;
    QTest::newRow("push flush") << "push" << "flush" << "skip" << true << false << false << false;
    QTest::newRow("push new") << "push" << "new" << "all" << true << false << true << false;
    QTest::newRow("push periodic skip") << "push" << "periodic" << "skip" << true << true << true
                                        << true;
}

void TestSeConnectorSettings::enablingRules()
{
    QFETCH(QString, dataflow);
    QFETCH(QString, subscription);
    QFETCH(QString, policy);
    ConnectorSettings s = ConnectorSettings::defaults("a", "b", "T");
    s.dataflowType = dataflow;
    s.subscriptionType = subscription;
    s.pushPolicy = policy;
    QTEST(s.isSubscriptionTypeEnabled(), "subscriptionOn");
    QTEST(s.isPushRateEnabled(), "rateOn");
    QTEST(s.isPushPolicyEnabled(), "policyOn");
    QTEST(s.isSkipCountEnabled(), "skipOn");
}

void TestSeConnectorSettings::applyWritesAttributesAndKeys()
{
    ConnectorSettings s = ConnectorSettings::defaults("a.out", "b.in", "RTC::TimedLong");
    s.subscriptionType = "periodic";
    s.pushRate = "20.5";
    s.pushPolicy = "skip";
    s.skipCount = "3";
    s.outBuffer.length = "8";
    s.outBuffer.fullPolicy = "block";
    s.inBuffer.readTimeout = "0.5";
    s.marshalingType = "cdr";
    RtsDataPortConnector c;
    s.applyTo(c);
    QCOMPARE(c.name, QStringLiteral("out_in"));
    QCOMPARE(c.dataType, QStringLiteral("RTC::TimedLong"));
    QCOMPARE(c.subscriptionType, std::optional<QString>("periodic"));
    QCOMPARE(c.pushInterval, std::optional<QString>("20.5"));
    const auto value = [&c](const char *key) { return rtsPropertyValue(c.properties, key); };
    QCOMPARE(value("dataport.push_rate"), std::optional<QString>("20.5"));
    QCOMPARE(value("dataport.publisher.push_policy"), std::optional<QString>("skip"));
    QCOMPARE(value("dataport.publisher.skip_count"), std::optional<QString>("3"));
    QCOMPARE(value("dataport.outport.buffer.length"), std::optional<QString>("8"));
    QCOMPARE(value("dataport.outport.buffer.write.full_policy"), std::optional<QString>("block"));
    QCOMPARE(value("dataport.inport.buffer.read.timeout"), std::optional<QString>("0.5"));
    QCOMPARE(value("dataport.inport.marshaling_type"), std::optional<QString>("cdr"));
    QCOMPARE(value("dataport.timestamp_policy"), std::optional<QString>("on_write"));
    QVERIFY(!value("dataport.inport.buffer.length"));
}

void TestSeConnectorSettings::disabledFieldsAreRemoved()
{
    ConnectorSettings s = ConnectorSettings::defaults("a", "b", "T");
    s.subscriptionType = "periodic";
    RtsDataPortConnector c;
    s.applyTo(c);
    QVERIFY(c.pushInterval);
    s.dataflowType = "pull";
    s.applyTo(c);
    QVERIFY(!c.pushInterval);
    QVERIFY(!c.subscriptionType);
    QVERIFY(!rtsPropertyValue(c.properties, "dataport.subscription_type"));
    QVERIFY(!rtsPropertyValue(c.properties, "dataport.publisher.push_policy"));
}

void TestSeConnectorSettings::readBackIsTheSame()
{
    ConnectorSettings s = ConnectorSettings::defaults("a", "b", "T");
    s.subscriptionType = "new";
    s.pushPolicy = "fifo";
    s.inBuffer.emptyPolicy = "do_nothing";
    s.freeProperties = {{"x.y", "1"}, {"z", ""}};
    RtsDataPortConnector c;
    s.applyTo(c);
    ConnectorSettings back = ConnectorSettings::fromConnector(c);
    // Disabled fields are not written and come back empty.
    s.pushRate.clear();
    s.skipCount.clear();
    QCOMPARE(back, s);
}

void TestSeConnectorSettings::freePropertiesKeepBendPoints()
{
    RtsDataPortConnector c;
    setRtsProperty(c.properties, "BEND_POINT", "{1:(1,2)}");
    setRtsProperty(c.properties, "old.free", "x");
    ConnectorSettings s = ConnectorSettings::fromConnector(c);
    QCOMPARE(s.freeProperties, (QList<QPair<QString, QString>> {{"old.free", "x"}}));
    s.freeProperties = {{"new.free", "y"}};
    s.dataflowType = "push";
    s.subscriptionType = "flush";
    s.interfaceType = "corba_cdr";
    s.name = "n";
    s.applyTo(c);
    QCOMPARE(rtsPropertyValue(c.properties, "BEND_POINT"), std::optional<QString>("{1:(1,2)}"));
    QVERIFY(!rtsPropertyValue(c.properties, "old.free"));
    QCOMPARE(rtsPropertyValue(c.properties, "new.free"), std::optional<QString>("y"));
}

void TestSeConnectorSettings::validation_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("messagePart");
    QTest::newRow("empty name") << "name" << "" << "name is empty";
    QTest::newRow("long name") << "name" << QString(256, 'x') << "longer than 255";
    QTest::newRow("rate zero") << "pushRate" << "0" << "push rate";
    QTest::newRow("rate text") << "pushRate" << "fast" << "push rate";
    QTest::newRow("skip negative") << "skipCount" << "-1" << "skip count";
    QTest::newRow("buffer zero") << "length" << "0" << "buffer length";
    QTest::newRow("full policy typo") << "fullPolicy" << "overerite" << "overerite";
    QTest::newRow("duplicate property") << "free" << "a" << "listed twice";
    QTest::newRow("standard key as free") << "free" << "dataport.push_rate" << "set by a field";
}

void TestSeConnectorSettings::validation()
{
    QFETCH(QString, field);
    QFETCH(QString, value);
    QFETCH(QString, messagePart);
    ConnectorSettings s = ConnectorSettings::defaults("a", "b", "T");
    s.subscriptionType = "periodic";
    s.pushPolicy = "skip";
    if (field == "name")
        s.name = value;
    else if (field == "pushRate")
        s.pushRate = value;
    else if (field == "skipCount")
        s.skipCount = value;
    else if (field == "length")
        s.outBuffer.length = value;
    else if (field == "fullPolicy")
        s.inBuffer.fullPolicy = value;
    else if (value == "a")
        s.freeProperties = {{"a", "1"}, {"a", "2"}};
    else
        s.freeProperties = {{value, "1"}};
    const QStringList problems = s.validate();
    QCOMPARE(problems.size(), 1);
    QVERIFY2(problems.first().contains(messagePart), qPrintable(problems.first()));
}

QTEST_GUILESS_MAIN(TestSeConnectorSettings)
#include "tst_seconnectorsettings.moc"
