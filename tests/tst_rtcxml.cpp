// SPDX-License-Identifier: MIT
// RTC.xml reading and writing with self-written fixtures: every field, unknown content kept in
// place, legacy spellings, missing required parts, broken files.
#include "namespaces.h"
#include "rtcfields_p.h"
#include "rtcvalidator.h"
#include "rtcxml.h"
#include "rtcyaml.h"
#include "tst_fieldtablesupport.h"
#include "xmlequivalence.h"

#include <QFile>
#include <QTest>

using namespace Profile;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + name;
}

QByteArray readData(const QString &name)
{
    QFile file(dataPath(name));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot open test data %s", qPrintable(name));
    return file.readAll();
}

QString errorsOf(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

RtcProfile load(const QString &name, Diagnostics *diagnostics = nullptr)
{
    Diagnostics local;
    Diagnostics &sink = diagnostics ? *diagnostics : local;
    const auto profile = readRtcXml(readData(name), name, &sink);
    if (!profile || hasErrors(sink))
        qFatal("cannot load %s: %s", qPrintable(name), qPrintable(errorsOf(sink)));
    return *profile;
}

/// The child elements of `node` called `name` (any namespace given).
std::vector<const XmlNode *> childrenNamed(const XmlNode &node, const QString &ns,
                                           const QString &name)
{
    std::vector<const XmlNode *> result;
    for (const XmlNode &child : node.children) {
        if (child.is(ns, name))
            result.push_back(&child);
    }
    return result;
}

int indexOfChild(const XmlNode &node, const QString &ns, const QString &name)
{
    for (std::size_t i = 0; i < node.children.size(); ++i) {
        if (node.children[i].is(ns, name))
            return int(i);
    }
    return -1;
}

QString attributeOf(const XmlNode &node, const QString &ns, const QString &name)
{
    const XmlAttribute *a = node.attribute(ns, name);
    return a ? a->value : QStringLiteral("<absent>");
}

const QString Future = QStringLiteral("urn:example:future");

/// Fills the RTC tables, their Special rows included.
class RtcFiller : public FieldTableFiller<RtcFiller, Fields::RtcElement>
{
public:
    /// The writers always write the current version.
    void fillSpecial(RtcProfile &profile, const Fields::Special<Fields::RtcProfileVersion> &)
    {
        profile.version = RtcProfile::CurrentVersion;
    }
    void fillSpecial(RtcProfile &profile, const Fields::Special<Fields::RtcConfigurationSet> &)
    {
        for (int i = 0; i < 2; ++i)
            fill(profile.configurations.emplace_back());
    }
    void fillSpecial(RtcActions &actions, const Fields::Special<Fields::RtcActionStatuses> &)
    {
        for (RtcAction action : rtcAllActions())
            fill(actions[action].emplace());
    }
    template<typename T>
    void fillSpecial(T &item, const Fields::Special<Fields::RtcConstraintTree> &)
    {
        item.constraint
            = RtcConstraint::between(next(Fields::Style::Number), next(Fields::Style::Number));
    }
};

} // namespace

class TestRtcXml : public QObject
{
    Q_OBJECT

private slots:
    void readsBasicInfo();
    void readsActions();
    void readsConfigurations();
    void readsConstraintTree();
    void readsDataPorts();
    void readsServicePorts();
    void readsLanguageAndParameters();
    void roundTripIsLossless();
    void everyTableFieldRoundTrips();
    void keepsUnknownContentInPlace();
    void keepsNarrowConfigurationType();
    void writesOpenRtpTypes();
    void readsLegacySpellings();
    void writesSchemaSpelling();
    void keepsMissingRequiredPartsAbsent();
    void writesDefaultProfile();
    void writesEditedModel();
    void reportsBrokenFiles_data();
    void reportsBrokenFiles();
    void readsHugeAttributeValue();
};

void TestRtcXml::readsBasicInfo()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    QCOMPARE(p.id, QStringLiteral("RTC:Acme:Sensor:Full:2.1.0"));
    QCOMPARE(p.version, QStringLiteral("0.3"));
    const RtcBasicInfo &b = p.basicInfo;
    QCOMPARE(b.name, QStringLiteral("Full"));
    QCOMPARE(b.componentType, QStringLiteral("UNIQUE"));
    QCOMPARE(b.activityType, QStringLiteral("SPORADIC"));
    QCOMPARE(b.componentKind, QStringLiteral("FiniteStateMachineComponent"));
    QCOMPARE(b.rtcType, QStringLiteral("Normal"));
    QCOMPARE(b.category, QStringLiteral("Sensor"));
    QCOMPARE(b.description, QStringLiteral("Every field"));
    QCOMPARE(b.executionRate, QStringLiteral("500.5"));
    QCOMPARE(b.executionRateValue().value_or(-1.0), 500.5);
    QCOMPARE(b.executionType, QStringLiteral("ExtTrigExecutionContext"));
    QCOMPARE(b.maxInstancesValue().value_or(-1), qint64(3));
    QCOMPARE(b.vendor, QStringLiteral("Acme"));
    QCOMPARE(b.version, QStringLiteral("2.1.0"));
    QCOMPARE(b.abstractText, QStringLiteral("An abstract"));
    QCOMPARE(b.hardwareProfile, QStringLiteral("HW"));
    QCOMPARE(b.creationDate, QStringLiteral("2020-01-02T03:04:05.000+09:00"));
    QCOMPARE(b.updateDate, QStringLiteral("2021-06-07T08:09:10.123+09:00"));
    QCOMPARE(b.comment, QStringLiteral("basic comment"));
    QCOMPARE(b.saveProject, QStringLiteral("FullProject"));
    QVERIFY(b.doc);
    QCOMPARE(b.doc->description, QStringLiteral("doc description"));
    QCOMPARE(b.doc->inout, QStringLiteral("doc inout"));
    QCOMPARE(b.doc->algorithm, QStringLiteral("doc algorithm"));
    QCOMPARE(b.doc->creator, QStringLiteral("Jane <jane@example.org>"));
    QCOMPARE(b.doc->license, QStringLiteral("MIT"));
    QCOMPARE(b.doc->reference, QStringLiteral("doc reference"));
    QCOMPARE(
        b.versionUpLogs,
        QStringList({QStringLiteral("2020/01/02 first"), QStringLiteral("2021/06/07 second")}));
    QCOMPARE(b.properties.size(), 2);
    QCOMPARE(rtcPropertyValue(b.properties, QStringLiteral("FSM")), QStringLiteral("true"));
    QCOMPARE(b.properties.at(1).value, std::nullopt);
    QCOMPARE(b.location.line, 3);
    QVERIFY(b.missing.isEmpty());
}

void TestRtcXml::readsActions()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    for (RtcAction action : rtcAllActions())
        QVERIFY2(p.actions[action], qPrintable(rtcActionElementName(action)));
    QVERIFY(p.actions.isImplemented(RtcAction::OnInitialize));
    QVERIFY(!p.actions.isImplemented(RtcAction::OnFinalize));
    QVERIFY(p.actions.isImplemented(RtcAction::OnExecute));
    QVERIFY(p.actions.isImplemented(RtcAction::OnAction));
    QVERIFY(!p.actions.isImplemented(RtcAction::OnModeChanged));
    const auto &init = p.actions[RtcAction::OnInitialize];
    QCOMPARE(init->doc->description, QStringLiteral("init"));
    QCOMPARE(init->doc->preCondition, QStringLiteral("init pre"));
    QCOMPARE(init->doc->postCondition, QStringLiteral("init post"));
    QCOMPARE(p.actions[RtcAction::OnModeChanged]->doc->postCondition, QStringLiteral("mode post"));
    QCOMPARE(p.actions[RtcAction::OnModeChanged]->doc->description, std::nullopt);
    QVERIFY(!p.actions[RtcAction::OnFinalize]->doc);
}

void TestRtcXml::readsConfigurations()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    QCOMPARE(p.configurations.size(), 4);
    const RtcConfiguration &gain = p.configurations.at(0);
    QCOMPARE(gain.name, QStringLiteral("gain"));
    QCOMPARE(gain.type, QStringLiteral("double"));
    QCOMPARE(gain.defaultValue, QStringLiteral("0.5"));
    QCOMPARE(gain.unit, QStringLiteral("V"));
    QCOMPARE(gain.variableName, QStringLiteral("gainVar"));
    QCOMPARE(gain.comment, QStringLiteral("gain comment"));
    QCOMPARE(gain.widget(), QStringLiteral("slider.0.1"));
    QVERIFY(gain.doc);
    QCOMPARE(gain.doc->dataname, QStringLiteral("gain"));
    QCOMPARE(gain.doc->defaultValue, QStringLiteral("0.5"));
    QCOMPARE(gain.doc->description, QStringLiteral("the gain"));
    QCOMPARE(gain.doc->unit, QStringLiteral("V"));
    QCOMPARE(gain.doc->range, QStringLiteral("0-1"));
    QCOMPARE(gain.doc->constraint, QStringLiteral("0<=x<=1"));
    const RtcConfiguration &table = p.configurations.at(2);
    QCOMPARE(table.defaultValue, QString());
    QVERIFY(!table.missing.contains(QStringLiteral("defaultValue")));
    QVERIFY(!table.variableName);
    QVERIFY(!p.hasConfigurationSet);
}

void TestRtcXml::readsConstraintTree()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    const RtcConstraint &range = *p.configurations.at(0).constraint;
    QCOMPARE(range.kind, RtcConstraintKind::Unit);
    QCOMPARE(range.op, RtcConstraintOperator::And);
    QCOMPARE(range.members.size(), std::size_t(2));
    QCOMPARE(range.members[0].op, RtcConstraintOperator::GreaterThanOrEqualTo);
    QCOMPARE(range.members[0].literal, QStringLiteral("0.0"));
    QCOMPARE(range.members[0].matchCase, QStringLiteral("false"));
    QCOMPARE(range.members[1].op, RtcConstraintOperator::LessThanOrEqualTo);

    const RtcConstraint &enumeration = *p.configurations.at(1).constraint;
    QCOMPARE(enumeration.op, RtcConstraintOperator::Or);
    QCOMPARE(enumeration.members[1].literal, QStringLiteral("slow"));
    QCOMPARE(enumeration.members[1].matchCase, QStringLiteral("true"));

    const RtcConstraint &hash = *p.configurations.at(2).constraint;
    QCOMPARE(hash.kind, RtcConstraintKind::Hash);
    QCOMPARE(hash.members.size(), std::size_t(3));
    QCOMPARE(hash.members[0].key, QStringLiteral("a"));
    QCOMPARE(hash.members[0].op, RtcConstraintOperator::Not);
    QCOMPARE(hash.members[0].members[0].op, RtcConstraintOperator::NotEqualTo);
    QCOMPARE(hash.members[1].op, RtcConstraintOperator::Like);
    QCOMPARE(hash.members[1].literal, QStringLiteral("ab*"));
    QCOMPARE(hash.members[1].wildCard, QStringLiteral("*"));
    QCOMPARE(hash.members[1].singleChar, QStringLiteral("?"));
    QCOMPARE(hash.members[1].escapeChar, QStringLiteral("\\"));
    QCOMPARE(hash.members[2].op, RtcConstraintOperator::IsNull);
    QCOMPARE(hash.members[2].literal, QStringLiteral("c"));

    const RtcConstraint &list = *p.configurations.at(3).constraint;
    QCOMPARE(list.kind, RtcConstraintKind::List);
    QCOMPARE(list.members[0].op, RtcConstraintOperator::LessThan);
    QCOMPARE(list.members[1].op, RtcConstraintOperator::GreaterThan);
    QCOMPARE(list.members[1].literal, QStringLiteral("-10"));

    const RtcConstraint &between = *p.dataPorts.at(0).constraint;
    QCOMPARE(between.op, RtcConstraintOperator::Between);
    QCOMPARE(between.literal, QStringLiteral("1"));
    QCOMPARE(between.upperBoundary, QStringLiteral("9"));
}

void TestRtcXml::readsDataPorts()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    QCOMPARE(p.dataPorts.size(), 3);
    const RtcDataPort &in = p.dataPorts.at(0);
    QCOMPARE(in.kind(), RtcPortType::DataIn);
    QCOMPARE(in.name, QStringLiteral("in"));
    QCOMPARE(in.type, QStringLiteral("RTC::TimedLong"));
    QCOMPARE(in.idlFile, QStringLiteral("BasicDataType.idl"));
    QCOMPARE(in.interfaceType, QStringLiteral("corba_cdr"));
    QCOMPARE(in.dataflowType, QStringLiteral("push"));
    QCOMPARE(in.subscriptionType, QStringLiteral("flush"));
    QCOMPARE(in.unit, QStringLiteral("m"));
    QCOMPARE(in.position, QStringLiteral("LEFT"));
    QCOMPARE(in.variableName, QStringLiteral("inVar"));
    QCOMPARE(in.comment, QStringLiteral("in comment"));
    QCOMPARE(in.doc->description, QStringLiteral("in doc"));
    QCOMPARE(in.doc->type, QStringLiteral("long"));
    QCOMPARE(in.doc->number, QStringLiteral("1"));
    QCOMPARE(in.doc->semantics, QStringLiteral("sem"));
    QCOMPARE(in.doc->unit, QStringLiteral("m"));
    QCOMPARE(in.doc->occerrence, QStringLiteral("often"));
    QCOMPARE(in.doc->operation, QStringLiteral("op"));
    QCOMPARE(rtcPropertyValue(in.properties, QStringLiteral("dataport.buffer.length")),
             QStringLiteral("8"));
    QCOMPARE(p.dataPorts.at(1).kind(), RtcPortType::DataOut);
    QVERIFY(!p.dataPorts.at(1).idlFile);

    const RtcDataPort &ev = p.dataPorts.at(2);
    QCOMPARE(ev.kind(), RtcPortType::Event);
    QCOMPARE(ev.position, QStringLiteral("TOP"));
    QCOMPARE(ev.events.size(), 2);
    const RtcEvent &go = ev.events.at(0);
    QCOMPARE(go.name, QStringLiteral("go"));
    QCOMPARE(go.condition, QStringLiteral("ready"));
    QCOMPARE(go.source, QStringLiteral("Idle"));
    QCOMPARE(go.target, QStringLiteral("Busy"));
    QCOMPARE(go.type, QStringLiteral("TimedLong"));
    QCOMPARE(go.doc->description, QStringLiteral("go doc"));
    QCOMPARE(go.doc->type, QStringLiteral("t"));
    QCOMPARE(go.doc->number, QStringLiteral("n"));
    QCOMPARE(go.doc->semantics, QStringLiteral("s"));
    QCOMPARE(go.doc->unit, QStringLiteral("u"));
    QCOMPARE(go.doc->operation, QStringLiteral("o"));
    QVERIFY(!ev.events.at(1).condition);
    QVERIFY(!ev.events.at(1).doc);
}

void TestRtcXml::readsServicePorts()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    QCOMPARE(p.servicePorts.size(), 1);
    const RtcServicePort &svc = p.servicePorts.at(0);
    QCOMPARE(svc.name, QStringLiteral("svc"));
    QCOMPARE(svc.position, QStringLiteral("BOTTOM"));
    QCOMPARE(svc.comment, QStringLiteral("svc comment"));
    QCOMPARE(svc.doc->description, QStringLiteral("svc doc"));
    QCOMPARE(svc.doc->ifdescription, QStringLiteral("svc if doc"));
    QCOMPARE(rtcPropertyValue(svc.properties, QStringLiteral("svcKey")),
             QStringLiteral("svcValue"));
    QCOMPARE(svc.transMethods.size(), 1);
    QCOMPARE(svc.transMethods.at(0).kind, QStringLiteral("CORBA"));
    QCOMPARE(svc.interfaces.size(), 2);
    const RtcServiceInterface &iface = svc.interfaces.at(0);
    QCOMPARE(iface.kind(), RtcDirection::Provided);
    QCOMPARE(iface.name, QStringLiteral("iface"));
    QCOMPARE(iface.instanceName, QStringLiteral("inst"));
    QCOMPARE(iface.idlFile, QStringLiteral("MyService.idl"));
    QCOMPARE(iface.type, QStringLiteral("SimpleService::MyService"));
    QCOMPARE(iface.path, QStringLiteral("idl"));
    QCOMPARE(iface.variableName, QStringLiteral("ifaceVar"));
    QCOMPARE(iface.comment, QStringLiteral("iface comment"));
    QCOMPARE(iface.doc->description, QStringLiteral("iface doc"));
    QCOMPARE(iface.doc->docArgument, QStringLiteral("arg"));
    QCOMPARE(iface.doc->docReturn, QStringLiteral("ret"));
    QCOMPARE(iface.doc->docException, QStringLiteral("exc"));
    QCOMPARE(iface.doc->docPreCondition, QStringLiteral("pre"));
    QCOMPARE(iface.doc->docPostCondition, QStringLiteral("post"));
    QCOMPARE(rtcPropertyValue(iface.properties, QStringLiteral("ifaceKey")),
             QStringLiteral("ifaceValue"));
    QCOMPARE(svc.interfaces.at(1).kind(), RtcDirection::Required);
}

void TestRtcXml::readsLanguageAndParameters()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    QVERIFY(p.language);
    QCOMPARE(p.language->kind, QStringLiteral("C++"));
    QCOMPARE(p.language->targets.size(), 1);
    const RtcTargetEnvironment &t = p.language->targets.at(0);
    QCOMPARE(t.langVersion, QStringLiteral("17"));
    QCOMPARE(t.os, QStringLiteral("Linux"));
    QCOMPARE(t.other, QStringLiteral("other"));
    QCOMPARE(t.cpuOther, QStringLiteral("riscv"));
    QCOMPARE(t.osVersions, QStringList {QStringLiteral("12")});
    QCOMPARE(t.cpus, QStringList({QStringLiteral("x86_64"), QStringLiteral("arm64")}));
    QCOMPARE(t.libraries.size(), 1);
    QCOMPARE(t.libraries.at(0).name, QStringLiteral("Eigen"));
    QCOMPARE(t.libraries.at(0).version, QStringLiteral("3.4"));
    QCOMPARE(t.libraries.at(0).other, QStringLiteral("header-only"));
    QCOMPARE(rtcPropertyValue(p.language->properties, QStringLiteral("langKey")),
             QStringLiteral("langValue"));
    QCOMPARE(p.parameters.size(), 1);
    QCOMPARE(p.parameters.at(0).name, QStringLiteral("param"));
    QCOMPARE(p.parameters.at(0).defaultValue, QStringLiteral("p0"));
}

void TestRtcXml::roundTripIsLossless()
{
    const QByteArray input = readData(QStringLiteral("rtc/full.xml"));
    const RtcProfile first = load(QStringLiteral("rtc/full.xml"));
    const QByteArray saved = writeRtcXml(first);
    Diagnostics diagnostics;
    const auto second = readRtcXml(saved, QStringLiteral("saved.xml"), &diagnostics);
    QVERIFY2(second, qPrintable(errorsOf(diagnostics)));
    QVERIFY2(diagnostics.isEmpty(), qPrintable(errorsOf(diagnostics)));
    QVERIFY(*second == first);
    QCOMPARE(writeRtcXml(*second), saved);

    const auto original = parseXml(input, QStringLiteral("full.xml"), nullptr);
    const auto written = parseXml(saved, QStringLiteral("saved.xml"), nullptr);
    QVERIFY(original && written);
    const QString difference = xmlDifference(*original, *written);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestRtcXml::everyTableFieldRoundTrips()
{
    RtcProfile profile;
    RtcFiller filler;
    filler.fill(profile);
    // Every element type of the component is reached, each with several fields.
    QVERIFY2(filler.scalarCount() > 300, qPrintable(QString::number(filler.scalarCount())));
    QVERIFY(profile.actions[RtcAction::OnModeChanged] && profile.language
            && profile.dataPorts.at(1).events.at(1).doc);

    Diagnostics diagnostics;
    const auto viaXml = readRtcXml(writeRtcXml(profile), QStringLiteral("table.xml"), &diagnostics);
    QVERIFY2(viaXml && diagnostics.isEmpty(), qPrintable(errorsOf(diagnostics)));
    QVERIFY(*viaXml == profile);

    const auto viaYaml
        = readRtcYaml(writeRtcYaml(profile), QStringLiteral("table.yaml"), &diagnostics);
    QVERIFY2(viaYaml && diagnostics.isEmpty(), qPrintable(errorsOf(diagnostics)));
    QVERIFY(*viaYaml == profile);
}

void TestRtcXml::keepsUnknownContentInPlace()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    const auto root = parseXml(writeRtcXml(p), QStringLiteral("saved.xml"), nullptr);
    QVERIFY(root);
    QCOMPARE(attributeOf(*root, Future, QStringLiteral("rootFlag")), QStringLiteral("yes"));
    QCOMPARE(indexOfChild(*root, Future, QStringLiteral("Trailer")),
             int(root->children.size()) - 1);

    const XmlNode &basic = root->children.at(0);
    QVERIFY(basic.is(Ns::Rtc, QStringLiteral("BasicInfo")));
    QCOMPARE(attributeOf(basic, Future, QStringLiteral("basicFlag")), QStringLiteral("kept"));
    QCOMPARE(indexOfChild(basic, Ns::RtcDoc, QStringLiteral("Doc")), 0);
    const int extra = indexOfChild(basic, Future, QStringLiteral("Extra"));
    QCOMPARE(extra, 1);
    QCOMPARE(basic.children.at(std::size_t(extra)).text, QStringLiteral("extra text"));
    QCOMPARE(attributeOf(basic.children.at(std::size_t(extra)), Future, QStringLiteral("where")),
             QStringLiteral("between Doc and VersionUpLogs"));
    QCOMPARE(indexOfChild(basic, Ns::RtcExt, QStringLiteral("VersionUpLogs")), 2);

    const auto ports = childrenNamed(*root, Ns::Rtc, QStringLiteral("DataPorts"));
    QCOMPARE(attributeOf(*ports.at(0), Future, QStringLiteral("portFlag")), QStringLiteral("1"));
    const auto languages = childrenNamed(*root, Ns::Rtc, QStringLiteral("Language"));
    QCOMPARE(indexOfChild(*languages.at(0), Future, QStringLiteral("Toolchain")), 0);
    QCOMPARE(indexOfChild(*languages.at(0), Ns::RtcExt, QStringLiteral("targets")), 1);
}

void TestRtcXml::keepsNarrowConfigurationType()
{
    // Older RTC Builder files type plain configurations rtcDoc:configuration_doc; saving keeps
    // that type until an extension field needs rtcExt:configuration_ext.
    const QByteArray file
        = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<rtc:RtcProfile rtc:version=\"0.2\" rtc:id=\"RTC:V:C:N:1.0.0\" "
          "xmlns:rtc=\"http://www.openrtp.org/namespaces/rtc\" "
          "xmlns:rtcDoc=\"http://www.openrtp.org/namespaces/rtc_doc\" "
          "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
          "  <rtc:BasicInfo rtc:name=\"N\" rtc:componentType=\"STATIC\" rtc:activityType=\"PERIODIC\" "
          "rtc:componentKind=\"DataFlowComponent\" rtc:category=\"C\" rtc:executionType=\"PeriodicExecutionContext\" "
          "rtc:vendor=\"V\" rtc:version=\"1.0.0\" rtc:creationDate=\"2008-01-01T00:00:00\" "
          "rtc:updateDate=\"2008-01-01T00:00:00\"/>\n"
          "  <rtc:ConfigurationSet>\n"
          "    <rtc:Configuration xsi:type=\"rtcDoc:configuration_doc\" rtc:name=\"a\" rtc:type=\"int\" "
          "rtc:defaultValue=\"1\"/>\n"
          "    <rtc:Configuration xsi:type=\"rtcDoc:configuration_doc\" rtc:name=\"b\" rtc:type=\"int\" "
          "rtc:defaultValue=\"2\"/>\n"
          "  </rtc:ConfigurationSet>\n"
          "</rtc:RtcProfile>\n";
    Diagnostics diagnostics;
    std::optional<RtcProfile> p = readRtcXml(file, QStringLiteral("old.xml"), &diagnostics);
    QVERIFY(p);
    p->configurations[1].variableName = QStringLiteral("bee");
    const auto root = parseXml(writeRtcXml(*p), QStringLiteral("saved.xml"), nullptr);
    QVERIFY(root);
    const XmlNode &set = *childrenNamed(*root, Ns::Rtc, QStringLiteral("ConfigurationSet")).front();
    QCOMPARE(set.children.at(0).xsiTypeNamespace, Ns::RtcDoc);
    QCOMPARE(set.children.at(0).xsiTypeName, QStringLiteral("configuration_doc"));
    QCOMPARE(set.children.at(1).xsiTypeNamespace, Ns::RtcExt);
    QCOMPARE(set.children.at(1).xsiTypeName, QStringLiteral("configuration_ext"));
}

void TestRtcXml::writesOpenRtpTypes()
{
    const RtcProfile p = load(QStringLiteral("rtc/full.xml"));
    const auto root = parseXml(writeRtcXml(p), QStringLiteral("saved.xml"), nullptr);
    QVERIFY(root);
    const QList<QPair<QString, QString>> expected
        = {{QStringLiteral("BasicInfo"), QStringLiteral("basic_info_ext")},
           {QStringLiteral("DataPorts"), QStringLiteral("dataport_ext")},
           {QStringLiteral("ServicePorts"), QStringLiteral("serviceport_ext")},
           {QStringLiteral("Language"), QStringLiteral("language_ext")}};
    for (const auto &entry : expected) {
        const auto nodes = childrenNamed(*root, Ns::Rtc, entry.first);
        QVERIFY2(!nodes.empty(), qPrintable(entry.first));
        QCOMPARE(nodes.front()->xsiTypeNamespace, Ns::RtcExt);
        QCOMPARE(nodes.front()->xsiTypeName, entry.second);
    }
    const XmlNode &actions = *childrenNamed(*root, Ns::Rtc, QStringLiteral("Actions")).front();
    QCOMPARE(actions.children.size(), std::size_t(RtcActionCount));
    for (const XmlNode &action : actions.children)
        QCOMPARE(action.xsiTypeName, QStringLiteral("action_status_doc"));
    const XmlNode &set = *childrenNamed(*root, Ns::Rtc, QStringLiteral("ConfigurationSet")).front();
    QCOMPARE(set.children.front().xsiTypeName, QStringLiteral("configuration_ext"));
    const XmlNode &service = *childrenNamed(*root, Ns::Rtc, QStringLiteral("ServicePorts")).front();
    QCOMPARE(service.children.front().xsiTypeName, QStringLiteral("serviceinterface_ext"));
    const XmlNode &eventPort = *childrenNamed(*root, Ns::Rtc, QStringLiteral("DataPorts")).at(2);
    QCOMPARE(eventPort.children.front().xsiTypeNamespace, Ns::RtcDoc);
    QCOMPARE(eventPort.children.front().xsiTypeName, QStringLiteral("event_doc"));
}

void TestRtcXml::readsLegacySpellings()
{
    const RtcProfile p = load(QStringLiteral("rtc/legacy.xml"));
    QCOMPARE(p.version, QStringLiteral("0.1"));
    QCOMPARE(p.basicInfo.versionUpLogs, QStringList {QStringLiteral("first")});
    QCOMPARE(p.configurations.at(0).variableName, QStringLiteral("rateVar"));
    const RtcDataPort &in = p.dataPorts.at(0);
    QCOMPARE(in.variableName, QStringLiteral("inVar"));
    QCOMPARE(in.position, QStringLiteral("LEFT"));
    QCOMPARE(in.subscriptionType, QStringLiteral("New"));
    QVERIFY(in.extras.isEmpty());
    QCOMPARE(p.servicePorts.at(0).position, QStringLiteral("TOP"));
    QCOMPARE(p.servicePorts.at(0).interfaces.at(0).variableName, QStringLiteral("svcVar"));
    QCOMPARE(p.servicePorts.at(0).interfaces.at(0).path, QStringLiteral("~/idl"));
    QCOMPARE(p.actions[RtcAction::OnInitialize]->implemented, QStringLiteral("true"));
    QVERIFY(p.actions.isImplemented(RtcAction::OnInitialize));
    QVERIFY(!p.actions.isImplemented(RtcAction::OnExecute));
    QVERIFY(!p.actions[RtcAction::OnFinalize]);
    // The per-language element of the 0.1 schema is not understood, so it is kept as it was.
    QVERIFY(p.language);
    QCOMPARE(p.language->missing, QStringList {QStringLiteral("kind")});
    QCOMPARE(p.language->extras.children.size(), std::size_t(1));
    QCOMPARE(p.language->extras.children.front().node.name, QStringLiteral("Cxx"));
}

void TestRtcXml::writesSchemaSpelling()
{
    const RtcProfile p = load(QStringLiteral("rtc/legacy.xml"));
    const QByteArray saved = writeRtcXml(p);
    QVERIFY(!saved.contains("varname"));
    QVERIFY(!saved.contains("subscriprionType"));
    QVERIFY(!saved.contains("VersionUpLog>"));
    const auto root = parseXml(saved, QStringLiteral("saved.xml"), nullptr);
    QVERIFY(root);
    QCOMPARE(attributeOf(*root, Ns::Rtc, QStringLiteral("version")), RtcProfile::CurrentVersion);
    const XmlNode &port = *childrenNamed(*root, Ns::Rtc, QStringLiteral("DataPorts")).front();
    QCOMPARE(attributeOf(port, Ns::RtcExt, QStringLiteral("variableName")),
             QStringLiteral("inVar"));
    QCOMPARE(attributeOf(port, Ns::RtcExt, QStringLiteral("position")), QStringLiteral("LEFT"));
    QCOMPARE(attributeOf(port, Ns::Rtc, QStringLiteral("subscriptionType")), QStringLiteral("New"));
    const XmlNode &actions = *childrenNamed(*root, Ns::Rtc, QStringLiteral("Actions")).front();
    QCOMPARE(attributeOf(actions.children.front(), Ns::Rtc, QStringLiteral("implemented")),
             QStringLiteral("true"));
    QCOMPARE(actions.children.size(), std::size_t(2));
    const XmlNode &configuration = childrenNamed(*root, Ns::Rtc, QStringLiteral("ConfigurationSet"))
                                       .front()
                                       ->children.front();
    QCOMPARE(configuration.xsiTypeName, QStringLiteral("configuration_ext"));
    QCOMPARE(attributeOf(configuration, Ns::RtcExt, QStringLiteral("variableName")),
             QStringLiteral("rateVar"));
    const XmlNode &basic = *childrenNamed(*root, Ns::Rtc, QStringLiteral("BasicInfo")).front();
    QCOMPARE(childrenNamed(basic, Ns::RtcExt, QStringLiteral("VersionUpLogs")).size(),
             std::size_t(1));

    // Load → save → load gives the same model (apart from the upgraded format version).
    Diagnostics diagnostics;
    auto again = readRtcXml(saved, QStringLiteral("saved.xml"), &diagnostics);
    QVERIFY(again);
    QCOMPARE(again->version, RtcProfile::CurrentVersion);
    again->version = p.version;
    QVERIFY(*again == p);
}

void TestRtcXml::keepsMissingRequiredPartsAbsent()
{
    Diagnostics diagnostics;
    const RtcProfile p = load(QStringLiteral("rtc/missing-required.xml"), &diagnostics);
    QVERIFY(!hasErrors(diagnostics));
    QVERIFY(diagnostics.size() >= 7);
    QCOMPARE(diagnostics.front().line, 2);
    QCOMPARE(diagnostics.front().severity, Diagnostic::Severity::Warning);
    QVERIFY(p.missing.contains(QStringLiteral("id")));
    QVERIFY(p.missing.contains(QStringLiteral("BasicInfo")));
    QVERIFY(p.missing.contains(QStringLiteral("Actions")));
    const RtcConfiguration &c = p.configurations.at(0);
    QCOMPARE(c.missing, QStringList({QStringLiteral("name"), QStringLiteral("type")}));
    QCOMPARE(c.constraint->missing, QStringList {QStringLiteral("Literal")});
    QCOMPARE(c.constraint->matchCase, std::nullopt);
    QCOMPARE(p.dataPorts.at(0).missing, QStringList {QStringLiteral("position")});

    const QByteArray saved = writeRtcXml(p);
    const auto original = parseXml(readData(QStringLiteral("rtc/missing-required.xml")),
                                   QStringLiteral("in"), nullptr);
    const auto written = parseXml(saved, QStringLiteral("out"), nullptr);
    QVERIFY(original && written);
    const QString difference = xmlDifference(*original, *written);
    QVERIFY2(difference.isEmpty(), qPrintable(difference + QLatin1Char('\n') + saved));

    const auto again = readRtcXml(saved, QStringLiteral("saved.xml"), nullptr);
    QVERIFY(again);
    QVERIFY(*again == p);

    // A value set later is written even though the source lacked it.
    RtcProfile edited = p;
    edited.configurations[0].name = QStringLiteral("named");
    QVERIFY(writeRtcXml(edited).contains("rtc:name=\"named\""));
}

void TestRtcXml::writesDefaultProfile()
{
    const RtcProfile p = RtcProfile::createDefault();
    QCOMPARE(p.id, QStringLiteral("RTC:VenderName:Category:ModuleName:1.0.0"));
    QCOMPARE(p.version, RtcProfile::CurrentVersion);
    QCOMPARE(p.basicInfo.name, QStringLiteral("ModuleName"));
    QCOMPARE(p.basicInfo.description, QStringLiteral("ModuleDescription"));
    QCOMPARE(p.basicInfo.category, QStringLiteral("Category"));
    QCOMPARE(p.basicInfo.version, QStringLiteral("1.0.0"));
    QCOMPARE(p.basicInfo.vendor, QStringLiteral("VenderName"));
    QCOMPARE(p.basicInfo.componentType, QStringLiteral("STATIC"));
    QCOMPARE(p.basicInfo.activityType, QStringLiteral("PERIODIC"));
    QCOMPARE(p.basicInfo.maxInstances, QStringLiteral("1"));
    QCOMPARE(p.basicInfo.executionType, QStringLiteral("PeriodicExecutionContext"));
    QCOMPARE(p.basicInfo.executionRate, QStringLiteral("1000.0"));
    QVERIFY(p.actions.isImplemented(RtcAction::OnInitialize));
    QVERIFY(!p.actions.isImplemented(RtcAction::OnExecute));
    QVERIFY(p.actions[RtcAction::OnModeChanged]);
    const QDateTime created = QDateTime::fromString(p.basicInfo.creationDate, Qt::ISODateWithMs);
    QVERIFY2(created.isValid(), qPrintable(p.basicInfo.creationDate));
    QVERIFY(qAbs(created.secsTo(QDateTime::currentDateTime())) < 600);
    QVERIFY(validateRtcProfile(p, QString()).isEmpty());

    Diagnostics diagnostics;
    const auto again = readRtcXml(writeRtcXml(p), QStringLiteral("new.xml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(errorsOf(diagnostics)));
    QVERIFY(*again == p);
}

void TestRtcXml::writesEditedModel()
{
    RtcProfile p = RtcProfile::createDefault();
    RtcDataPort port;
    port.portType = rtcPortTypeText(RtcPortType::DataOut);
    port.name = QStringLiteral("out");
    port.type = QStringLiteral("RTC::TimedLong");
    port.position = QStringLiteral("RIGHT");
    p.dataPorts.append(port);
    RtcConfiguration c;
    c.name = QStringLiteral("speed");
    c.type = QStringLiteral("int");
    c.defaultValue = QStringLiteral("5");
    c.constraint
        = RtcConstraint::logical(RtcConstraintOperator::Or,
                                 {RtcConstraint::comparison(RtcConstraintOperator::EqualTo, "1"),
                                  RtcConstraint::comparison(RtcConstraintOperator::EqualTo, "5")});
    setRtcProperty(c.properties, RtcConfiguration::WidgetProperty, QStringLiteral("radio"));
    p.configurations.append(c);
    const auto again = readRtcXml(writeRtcXml(p), QStringLiteral("edited.xml"), nullptr);
    QVERIFY(again);
    QVERIFY(*again == p);
    QCOMPARE(again->configurations.at(0).widget(), QStringLiteral("radio"));
    QCOMPARE(again->dataPorts.at(0).kind(), RtcPortType::DataOut);
}

void TestRtcXml::reportsBrokenFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");
    QTest::newRow("truncated") << "truncated.xml" << 5 << "end of file";
    QTest::newRow("wrong root") << "wrong-root.xml" << 3 << "RtsProfile";
    QTest::newRow("wrong namespace") << "wrong-namespace.xml" << 3 << "rtc_v9";
    QTest::newRow("invalid UTF-8") << "invalid-utf8.xml" << 4 << "UTF-8";
    QTest::newRow("deep nesting") << "deep-nesting.xml" << 89 << "deeper";
    QTest::newRow("entity expansion") << "entity-expansion.xml" << 15 << "expansion limit";
    QTest::newRow("not XML") << "not-xml.xml" << 1 << "";
}

void TestRtcXml::reportsBrokenFiles()
{
    QFETCH(QString, file);
    QFETCH(int, line);
    QFETCH(QString, message);
    const QString name = QStringLiteral("rtc-broken/") + file;
    Diagnostics diagnostics;
    const auto profile = readRtcXml(readData(name), name, &diagnostics);
    QVERIFY(!profile);
    QVERIFY(hasErrors(diagnostics));
    const Diagnostic &first = diagnostics.front();
    QCOMPARE(first.severity, Diagnostic::Severity::Error);
    QCOMPARE(first.file, name);
    QCOMPARE(first.line, line);
    QVERIFY(first.column > 0);
    QVERIFY2(first.message.contains(message), qPrintable(first.message));
    QVERIFY(first.toString().startsWith(name + QLatin1Char(':') + QString::number(line)
                                        + QLatin1Char(':')));
}

void TestRtcXml::readsHugeAttributeValue()
{
    QByteArray data = readData(QStringLiteral("rtc-broken/huge-attribute.xml"));
    const QByteArray huge = QByteArray(4 * 1024 * 1024, '9') + "x";
    data.replace("@HUGE@", huge);
    Diagnostics diagnostics;
    const auto profile = readRtcXml(data, QStringLiteral("huge.xml"), &diagnostics);
    QVERIFY2(profile, qPrintable(errorsOf(diagnostics)));
    QCOMPARE(profile->basicInfo.maxInstances->size(), huge.size());
    const Diagnostics findings = validateRtcProfile(*profile, QStringLiteral("huge.xml"));
    QVERIFY(hasErrors(findings));
    QCOMPARE(findings.front().line, 3);
    QVERIFY(findings.front().message.contains(QStringLiteral("maximum number of instances")));
}

QTEST_GUILESS_MAIN(TestRtcXml)
#include "tst_rtcxml.moc"
