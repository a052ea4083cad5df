// SPDX-License-Identifier: MIT
#include "namespaces.h"
#include "xmlextras.h"
#include "xmlnode.h"

#include <QTest>

using namespace Profile;

class TestXmlNode : public QObject
{
    Q_OBJECT

private slots:
    void parsesNamespacesAndXsiType();
    void locatesMultiLineStartTags();
    void roundTripsThroughSerialisation();
    void namespaceUrisNeedingEscapesRoundTrip();
    void reportsErrorsWithPosition_data();
    void reportsErrorsWithPosition();
    void rejectsDeepNesting();
    void keepsUnconsumedContentAsExtras();
    void parsesBooleans();
};

void TestXmlNode::parsesNamespacesAndXsiType()
{
    const QByteArray xml = R"(<?xml version="1.0"?>
<a:RtcProfile xmlns:a="http://www.openrtp.org/namespaces/rtc"
              xmlns:x="http://www.openrtp.org/namespaces/rtc_ext"
              xmlns:i="http://www.w3.org/2001/XMLSchema-instance" a:id="RTC:v:c:n:1">
  <a:BasicInfo i:type="x:basic_info_ext" a:name="N"><x:VersionUpLogs>log 1</x:VersionUpLogs></a:BasicInfo>
</a:RtcProfile>)";
    Diagnostics diagnostics;
    const auto root = parseXml(xml, QStringLiteral("t.xml"), &diagnostics);
    QVERIFY2(root, qPrintable(diagnostics.value(0).toString()));
    QVERIFY(root->is(Ns::Rtc, QStringLiteral("RtcProfile")));
    QVERIFY(root->attribute(Ns::Rtc, QStringLiteral("id")));
    QCOMPARE(root->attribute(Ns::Rtc, QStringLiteral("id"))->value, QStringLiteral("RTC:v:c:n:1"));
    QCOMPARE(root->children.size(), std::size_t(1));
    const XmlNode &basic = root->children.front();
    QCOMPARE(basic.xsiTypeNamespace, Ns::RtcExt);
    QCOMPARE(basic.xsiTypeName, QStringLiteral("basic_info_ext"));
    QVERIFY(!basic.attribute(Ns::Xsi, QStringLiteral("type")));
    QCOMPARE(basic.children.front().text, QStringLiteral("log 1"));
    QCOMPARE(basic.location.line, 5);
    QCOMPARE(basic.location.column, 3);
}

void TestXmlNode::locatesMultiLineStartTags()
{
    const QByteArray xml = "<r>\n  <a x=\"1\"\n     y=\"2\"/>\n  <b/></r>";
    Diagnostics diagnostics;
    const auto root = parseXml(xml, QStringLiteral("t.xml"), &diagnostics);
    QVERIFY(root);
    QCOMPARE(root->location.line, 1);
    QCOMPARE(root->location.column, 1);
    QCOMPARE(root->children.at(0).location.line, 2);
    QCOMPARE(root->children.at(0).location.column, 3);
    QCOMPARE(root->children.at(1).location.line, 4);
}

void TestXmlNode::roundTripsThroughSerialisation()
{
    XmlNode root(Ns::Rts, QStringLiteral("RtsProfile"));
    root.setAttribute(Ns::Rts, QStringLiteral("id"), QStringLiteral("RTSystem:v:n:1"));
    XmlNode &component = root.addChild(Ns::Rts, QStringLiteral("Components"));
    component.setXsiType(Ns::RtsExt, QStringLiteral("component_ext"));
    component.setAttribute(Ns::Rts, QStringLiteral("instanceName"), QStringLiteral("A & <B>"));
    XmlNode &future = component.addChild(QStringLiteral("urn:future"), QStringLiteral("Thing"));
    future.prefix = QStringLiteral("fut");
    future.text = QStringLiteral("kept");

    const QByteArray text = serializeXml(root);
    QVERIFY(text.contains("<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\""));
    QVERIFY(!text.contains("xmlns:n1"));
    QVERIFY(text.contains("xsi:type=\"rtsExt:component_ext\""));
    QVERIFY(text.contains("xmlns:fut=\"urn:future\""));
    Diagnostics diagnostics;
    const auto again = parseXml(text, QStringLiteral("t.xml"), &diagnostics);
    QVERIFY(again);
    QVERIFY(*again == root);
}

// QXmlStreamWriter writes a namespace declaration as it is given: a URI with characters that need
// escaping (read from a file that escaped them) once made a file that did not read back.
void TestXmlNode::namespaceUrisNeedingEscapesRoundTrip()
{
    const QByteArray xml = "<?xml version=\"1.0\"?>\n"
                           "<r xmlns:a=\"urn:x?p=1&amp;q=&lt;2&gt;&quot;\" xmlns:b=\"urn:tab&#9;line&#10;end\""
                           " xmlns:unused=\"http://example.org &lt;author@example.org&gt;\">"
                           "<a:child a:name=\"v\" b:other=\"w\"/></r>";
    Diagnostics diagnostics;
    const auto root = parseXml(xml, QStringLiteral("t.xml"), &diagnostics);
    QVERIFY2(root, qPrintable(diagnostics.value(0).toString()));
    QCOMPARE(root->children.front().namespaceUri, QStringLiteral("urn:x?p=1&q=<2>\""));
    const QByteArray text = serializeXml(*root);
    Diagnostics again;
    const auto reread = parseXml(text, QStringLiteral("saved.xml"), &again);
    QVERIFY2(reread, qPrintable(again.value(0).toString() + QLatin1Char('\n') + QString::fromUtf8(text)));
    QVERIFY2(*reread == *root, text.constData());
    QCOMPARE(reread->children.front().attributes.at(1).namespaceUri, QStringLiteral("urn:tab\tline\nend"));
}

void TestXmlNode::reportsErrorsWithPosition_data()
{
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("fragment");
    QTest::newRow("truncated") << QByteArray("<a>\n<b x=\"1\">\n") << 3 << QStringLiteral("");
    QTest::newRow("empty") << QByteArray("") << 1 << QStringLiteral("no root element");
    QTest::newRow("invalid utf-8") << QByteArray("<a>\n<b x=\"\xff\xfe\"/></a>") << 2
                                   << QStringLiteral("UTF-8");
    QTest::newRow("mismatched tag") << QByteArray("<a>\n\n<b></c></a>") << 3 << QStringLiteral("");
    QTest::newRow("two roots") << QByteArray("<a/>\n<b/>") << 2 << QStringLiteral("");
}

void TestXmlNode::reportsErrorsWithPosition()
{
    QFETCH(QByteArray, data);
    QFETCH(int, line);
    QFETCH(QString, fragment);
    Diagnostics diagnostics;
    const auto root = parseXml(data, QStringLiteral("bad.xml"), &diagnostics);
    QVERIFY(!root);
    QCOMPARE(diagnostics.size(), 1);
    QCOMPARE(diagnostics.first().line, line);
    QVERIFY(diagnostics.first().toString().startsWith(QStringLiteral("bad.xml:%1:").arg(line)));
    QVERIFY2(diagnostics.first().message.contains(fragment), qPrintable(diagnostics.first().message));
}

void TestXmlNode::rejectsDeepNesting()
{
    QByteArray data;
    for (int i = 0; i < 5000; ++i)
        data += "<a>";
    Diagnostics diagnostics;
    QVERIFY(!parseXml(data, QStringLiteral("deep.xml"), &diagnostics));
    QVERIFY(diagnostics.first().message.contains(QStringLiteral("nested")));
}

void TestXmlNode::keepsUnconsumedContentAsExtras()
{
    const QByteArray xml = R"(<r:P xmlns:r="http://www.openrtp.org/namespaces/rts" xmlns:f="urn:f"
        r:known="1" f:unknown="2"><r:A/><f:New>x</f:New><r:B/></r:P>)";
    Diagnostics diagnostics;
    const auto root = parseXml(xml, QStringLiteral("t.xml"), &diagnostics);
    QVERIFY(root);
    NodeReader reader(*root, QStringLiteral("t.xml"), &diagnostics);
    QCOMPARE(reader.attribute(Ns::Rts, QStringLiteral("known")).value_or(QString()),
             QStringLiteral("1"));
    QCOMPARE(reader.children(Ns::Rts, QStringLiteral("A")).size(), std::size_t(1));
    QVERIFY(reader.child(Ns::Rts, QStringLiteral("B")));
    QVERIFY(reader.required(Ns::Rts, QStringLiteral("missing")).isEmpty());
    QCOMPARE(diagnostics.size(), 1);
    const XmlExtras extras = reader.extras();
    QCOMPARE(extras.attributes.size(), 1);
    QCOMPARE(extras.attributes.first().name, QStringLiteral("unknown"));
    QCOMPARE(extras.children.size(), std::size_t(1));
    QCOMPARE(extras.children.front().position, 1);

    XmlNode rebuilt(Ns::Rts, QStringLiteral("P"));
    rebuilt.setAttribute(Ns::Rts, QStringLiteral("known"), QStringLiteral("1"));
    rebuilt.addChild(Ns::Rts, QStringLiteral("A"));
    rebuilt.addChild(Ns::Rts, QStringLiteral("B"));
    extras.applyTo(rebuilt);
    QCOMPARE(rebuilt.children.at(1).name, QStringLiteral("New"));
    QCOMPARE(rebuilt.children.at(1).text, QStringLiteral("x"));
    QCOMPARE(rebuilt.attributes.size(), 2);
}

void TestXmlNode::parsesBooleans()
{
    QCOMPARE(parseBoolean(QStringLiteral("TRUE")), std::optional<bool>(true));
    QCOMPARE(parseBoolean(QStringLiteral("0")), std::optional<bool>(false));
    QCOMPARE(parseBoolean(QStringLiteral("yes")), std::optional<bool>());
}

QTEST_GUILESS_MAIN(TestXmlNode)
#include "tst_xmlnode.moc"
