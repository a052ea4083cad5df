// SPDX-License-Identifier: MIT
#include "xmlequivalence.h"

#include <QTest>

using namespace Profile;

// The comparator decides whether conformance files survive a round trip, so it must notice real
// differences as surely as it forgives cosmetic ones.
class TestXmlEquivalence : public QObject
{
    Q_OBJECT

private slots:
    void compares_data();
    void compares();
    void appliesNormalization();
};

static XmlNode parse(const QByteArray &xml)
{
    Diagnostics diagnostics;
    const auto node = parseXml(xml, QStringLiteral("t.xml"), &diagnostics);
    return node.value_or(XmlNode());
}

void TestXmlEquivalence::compares_data()
{
    QTest::addColumn<QByteArray>("a");
    QTest::addColumn<QByteArray>("b");
    QTest::addColumn<bool>("equivalent");
    const QByteArray base = R"(<p:R xmlns:p="urn:p" p:x="1" p:y="2"><p:A p:n="a"/><p:B>t</p:B></p:R>)";
    QTest::newRow("same") << base << base << true;
    QTest::newRow("attribute order, prefix, whitespace, child order")
        << base
        << QByteArray(R"(<q:R xmlns:q="urn:p" q:y="2" q:x="1">
              <q:B>t</q:B>
              <q:A q:n="a"/>
           </q:R>)")
        << true;
    QTest::newRow("value changed")
        << base << QByteArray(R"(<p:R xmlns:p="urn:p" p:x="1" p:y="3"><p:A p:n="a"/><p:B>t</p:B></p:R>)")
        << false;
    QTest::newRow("attribute lost")
        << base << QByteArray(R"(<p:R xmlns:p="urn:p" p:x="1"><p:A p:n="a"/><p:B>t</p:B></p:R>)")
        << false;
    QTest::newRow("child lost")
        << base << QByteArray(R"(<p:R xmlns:p="urn:p" p:x="1" p:y="2"><p:B>t</p:B></p:R>)") << false;
    QTest::newRow("text changed")
        << base << QByteArray(R"(<p:R xmlns:p="urn:p" p:x="1" p:y="2"><p:A p:n="a"/><p:B>u</p:B></p:R>)")
        << false;
    QTest::newRow("other namespace")
        << base << QByteArray(R"(<p:R xmlns:p="urn:q" p:x="1" p:y="2"><p:A p:n="a"/><p:B>t</p:B></p:R>)")
        << false;
    QTest::newRow("duplicate child lost")
        << QByteArray(R"(<p:R xmlns:p="urn:p"><p:A/><p:A/></p:R>)")
        << QByteArray(R"(<p:R xmlns:p="urn:p"><p:A/></p:R>)") << false;
}

void TestXmlEquivalence::compares()
{
    QFETCH(QByteArray, a);
    QFETCH(QByteArray, b);
    QFETCH(bool, equivalent);
    const QString difference = xmlDifference(parse(a), parse(b));
    QCOMPARE(difference.isEmpty(), equivalent);
}

void TestXmlEquivalence::appliesNormalization()
{
    const XmlNode legacy = parse(R"(<p:R xmlns:p="urn:p" p:varname="v" p:pos="left" p:on="1"><p:Old/></p:R>)");
    const XmlNode current = parse(R"(<p:R xmlns:p="urn:p" p:variableName="v" p:pos="LEFT" p:on="true"><p:New/></p:R>)");
    QVERIFY(!xmlDifference(legacy, current).isEmpty());

    XmlNormalization n;
    n.attributeRenames.insert(XmlNormalization::key("urn:p", "varname"),
                              XmlNormalization::key("urn:p", "variableName"));
    n.elementRenames.insert(XmlNormalization::key("urn:p", "Old"), XmlNormalization::key("urn:p", "New"));
    n.valueNormalizers.insert(XmlNormalization::key("urn:p", "pos"), &XmlNormalization::upperCase);
    n.valueNormalizers.insert(XmlNormalization::key("urn:p", "on"), &XmlNormalization::boolean);
    QCOMPARE(xmlDifference(legacy, current, n), QString());
}

QTEST_GUILESS_MAIN(TestXmlEquivalence)
#include "tst_xmlequivalence.moc"
