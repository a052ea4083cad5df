// SPDX-License-Identifier: MIT
#include "namespaces.h"
#include "rtsfields_p.h"
#include "rtsxml.h"
#include "rtsyaml.h"
#include "tst_fieldtablesupport.h"
#include "xmlequivalence.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QRegularExpression>
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
    const auto profile = readRtsXml(readFile(dataPath(name)), name, &diagnostics);
    if (!profile || !diagnostics.isEmpty())
        qWarning().noquote() << name << joined(diagnostics);
    return profile.value_or(RtsProfile());
}

XmlNormalization rtsQuirks()
{
    XmlNormalization n;
    n.elementRenames.insert(XmlNormalization::key(Ns::RtsExt, QStringLiteral("VersionUpLog")),
                            XmlNormalization::key(Ns::RtsExt, QStringLiteral("VersionUpLogs")));
    n.attributeRenames.insert(XmlNormalization::key(Ns::Rts, QStringLiteral("groupID")),
                              XmlNormalization::key(Ns::Rts, QStringLiteral("groupId")));
    n.valueNormalizers.insert(XmlNormalization::key(Ns::RtsExt, QStringLiteral("direction")),
                              &XmlNormalization::upperCase);
    for (const char *attribute : {"isRequired", "visible"}) {
        n.valueNormalizers.insert(XmlNormalization::key(Ns::Rts, QLatin1String(attribute)),
                                  &XmlNormalization::boolean);
        n.valueNormalizers.insert(XmlNormalization::key(Ns::RtsExt, QLatin1String(attribute)),
                                  &XmlNormalization::boolean);
    }
    return n;
}

const XmlNode *childAt(const XmlNode &node, const QString &ns, const QString &name, int nth = 0)
{
    for (const XmlNode &child : node.children) {
        if (child.is(ns, name) && nth-- == 0)
            return &child;
    }
    return nullptr;
}

int indexOfChild(const XmlNode &node, const QString &ns, const QString &name)
{
    for (std::size_t i = 0; i < node.children.size(); ++i) {
        if (node.children[i].is(ns, name))
            return int(i);
    }
    return -1;
}

/// The RTS tables have no Special rows.
class RtsFiller : public FieldTableFiller<RtsFiller, Fields::RtsElement>
{
};

} // namespace

class TestRtsXml : public QObject
{
    Q_OBJECT

private slots:
    void readsSystemAttributes();
    void readsComponents();
    void readsConnectorsAndGroups();
    void readsMessageSequences();
    void readsExtension();
    void mapsLegacySpellings();
    void keepsUnknownContentInPlace();
    void keepsRootExtensionType();
    void writesSchemaFormWithXsiTypes();
    void roundTrips_data();
    void roundTrips();
    void everyTableFieldRoundTrips();
    void editedModelSurvivesSaving();
    void rejectsBrokenFiles_data();
    void rejectsBrokenFiles();
    void reportsMissingRequiredParts();
    void loadsAndSavesLargeSystems();
};

void TestRtsXml::readsSystemAttributes()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    QCOMPARE(p.id, QStringLiteral("RTSystem:TestVendor:FullSystem:2.1"));
    QCOMPARE(p.version, QStringLiteral("0.2"));
    QCOMPARE(p.abstract, std::optional<QString>(QStringLiteral("Everything the schema has")));
    QCOMPARE(p.creationDate, QStringLiteral("2024-01-02T03:04:05.678+09:00"));
    QCOMPARE(p.updateDate, QStringLiteral("2024-02-03T04:05:06"));
    QCOMPARE(p.comment, std::optional<QString>(QStringLiteral("System comment")));
    QVERIFY(p.systemId());
    QCOMPARE(p.systemId()->vendor, QStringLiteral("TestVendor"));
    QCOMPARE(p.systemId()->name, QStringLiteral("FullSystem"));
    QCOMPARE(p.systemId()->version, QStringLiteral("2.1"));
    QCOMPARE(p.location.line, 4);
}

void TestRtsXml::readsComponents()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    QCOMPARE(p.components.size(), 3);
    const RtsComponent *camera = p.component(QStringLiteral("Camera0"));
    QVERIFY(camera);
    QCOMPARE(camera->id, QStringLiteral("RTC:TestVendor:Sensor:Camera:1.0.0"));
    QCOMPARE(camera->pathUri, QStringLiteral("localhost/camera0.rtc"));
    QCOMPARE(camera->activeConfigurationSet, std::optional<QString>(QStringLiteral("default")));
    QCOMPARE(camera->compositeType, std::optional<QString>(QStringLiteral("None")));
    QVERIFY(camera->isRequiredValue());
    QCOMPARE(camera->comment, std::optional<QString>(QStringLiteral("The camera")));
    QCOMPARE(camera->visible, std::optional<QString>(QStringLiteral("true")));

    QCOMPARE(camera->dataPorts.size(), 2);
    QCOMPARE(camera->dataPorts.at(0).comment, std::optional<QString>(QStringLiteral("images out")));
    QCOMPARE(rtsPropertyValue(camera->dataPorts.at(0).properties, QStringLiteral("port.port_type")),
             std::optional<QString>(QStringLiteral("DataOutPort")));
    QCOMPARE(camera->dataPorts.at(1).visible, std::optional<QString>(QStringLiteral("false")));
    QVERIFY(camera->servicePort(QStringLiteral("Camera0.control")));
    QVERIFY(camera->hasPort(QStringLiteral("Camera0.trigger")));
    QVERIFY(!camera->hasPort(QStringLiteral("Camera0.none")));

    QCOMPARE(camera->configurationSets.size(), 2);
    const RtsConfigurationSet &set = camera->configurationSets.at(0);
    QCOMPARE(set.data.size(), 3);
    QCOMPARE(set.data.at(1).name, QStringLiteral("height"));
    QCOMPARE(set.data.at(1).data, std::optional<QString>(QStringLiteral("480")));
    QCOMPARE(set.data.at(2).data, std::nullopt);

    QCOMPARE(camera->executionContexts.size(), 2);
    const RtsExecutionContext &ec = camera->executionContexts.at(0);
    QCOMPARE(ec.kind, QStringLiteral("PeriodicExecutionContext"));
    QCOMPARE(ec.rateValue(), std::optional<double>(30.0));
    QCOMPARE(ec.participants.size(), 1);
    QCOMPARE(ec.participants.at(0).instanceName, QStringLiteral("Blur0"));
    QCOMPARE(ec.participants.at(0).properties.size(), 1);
    QCOMPARE(ec.properties.at(0).value, std::optional<QString>(QStringLiteral("YES")));
    QVERIFY(camera->executionContext(QStringLiteral("CameraEc1")));
    QCOMPARE(camera->executionContext(QStringLiteral("CameraEc1"))->rate, std::nullopt);

    QVERIFY(camera->layout);
    QCOMPARE(camera->layout->x, QStringLiteral("10"));
    QCOMPARE(camera->layout->y, QStringLiteral("20"));
    QCOMPARE(camera->layout->direction, QStringLiteral("RIGHT"));
    QCOMPARE(camera->properties.size(), 3);
    QCOMPARE(camera->properties.at(2).value, std::nullopt);

    const RtsComponent *blur = p.component(QStringLiteral("Blur0"));
    QVERIFY(blur);
    QVERIFY(!blur->isRequiredValue());
    QCOMPARE(blur->activeConfigurationSet, std::nullopt);
    QCOMPARE(blur->comment, std::nullopt);

    const RtsComponent *pipeline = p.component(QStringLiteral("Pipeline0"));
    QVERIFY(pipeline);
    QCOMPARE(pipeline->compositeType, std::optional<QString>(QStringLiteral("PeriodicECShared")));
    QCOMPARE(pipeline->participants.size(), 2);
    QCOMPARE(pipeline->participants.at(1).participant.instanceName, QStringLiteral("Blur0"));
    QCOMPARE(pipeline->participants.at(1).participant.properties.at(0).name,
             QStringLiteral("order"));
    QCOMPARE(pipeline->layout->direction, QStringLiteral("DOWN"));
    QCOMPARE(p.componentIndex().value(QStringLiteral("Pipeline0")), 2);
}

void TestRtsXml::readsConnectorsAndGroups()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    QCOMPARE(p.groups.size(), 1);
    QCOMPARE(p.groups.at(0).groupId, QStringLiteral("sensors"));
    QCOMPARE(p.groups.at(0).members.size(), 2);

    QCOMPARE(p.dataPortConnectors.size(), 2);
    const RtsDataPortConnector *image = p.dataPortConnector(QStringLiteral("c-image"));
    QVERIFY(image);
    QCOMPARE(image->name, QStringLiteral("image_in"));
    QCOMPARE(image->dataType, QStringLiteral("IDL:RTC/CameraImage:1.0"));
    QCOMPARE(image->interfaceType, QStringLiteral("corba_cdr"));
    QCOMPARE(image->dataflowType, QStringLiteral("push"));
    QCOMPARE(image->subscriptionType, std::optional<QString>(QStringLiteral("periodic")));
    QCOMPARE(image->pushInterval, std::optional<QString>(QStringLiteral("15.0")));
    QCOMPARE(image->comment, std::optional<QString>(QStringLiteral("image stream")));
    QCOMPARE(image->source.instanceName, QStringLiteral("Camera0"));
    QCOMPARE(image->source.portName, QStringLiteral("Camera0.image"));
    QCOMPARE(image->target.portName, QStringLiteral("Blur0.in"));
    QCOMPARE(rtsPropertyValue(image->target.properties, QStringLiteral("COMPONENT_PATH_ID")),
             std::optional<QString>(QStringLiteral("localhost/blur0.rtc")));
    QCOMPARE(rtsPropertyValue(image->properties, QStringLiteral("BEND_POINT")),
             std::optional<QString>(QStringLiteral("{1:(150,30)}")));
    QCOMPARE(p.dataPortConnector(QStringLiteral("c-trigger"))->subscriptionType, std::nullopt);

    const RtsServicePortConnector *control = p.servicePortConnector(QStringLiteral("c-control"));
    QVERIFY(control);
    QCOMPARE(control->transMethod, std::optional<QString>(QStringLiteral("corba")));
    QCOMPARE(control->visible, std::optional<QString>(QStringLiteral("false")));
    QCOMPARE(control->target.portName, QStringLiteral("Blur0.control"));
    QCOMPARE(control->properties.size(), 1);
    QCOMPARE(p.connector(QStringLiteral("c-control")), control);
    QCOMPARE(p.connector(QStringLiteral("c-image")), image);
    QCOMPARE(p.connector(QStringLiteral("nothing")), nullptr);
}

void TestRtsXml::readsMessageSequences()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    QVERIFY(p.startUp);
    QCOMPARE(p.startUp->targets.size(), 2);
    const RtsCondition &first = p.startUp->targets.at(0);
    QCOMPARE(first.sequence, QStringLiteral("0"));
    QCOMPARE(first.targetComponent.instanceName, QStringLiteral("Camera0"));
    QCOMPARE(first.targetComponent.id, QStringLiteral("0"));
    QVERIFY(first.waitTime);
    QCOMPARE(first.waitTime->waitTime, std::optional<QString>(QStringLiteral("100")));
    QVERIFY(!first.preceding);
    QCOMPARE(first.properties.at(0).value, std::optional<QString>(QStringLiteral("first")));
    const RtsCondition &second = p.startUp->targets.at(1);
    QVERIFY(second.preceding);
    QCOMPARE(second.preceding->timeout, std::optional<QString>(QStringLiteral("500")));
    QCOMPARE(second.preceding->sendingTiming, std::optional<QString>(QStringLiteral("SYNC")));
    QCOMPARE(second.preceding->precedingComponents.size(), 1);

    QVERIFY(p.shutDown);
    const RtsPreceding &preceding = *p.shutDown->targets.at(0).preceding;
    QCOMPARE(preceding.timeout, std::nullopt);
    QCOMPARE(preceding.precedingComponents.size(), 2);
    QCOMPARE(preceding.precedingComponents.at(1).instanceName, QStringLiteral("Pipeline0"));
    QCOMPARE(p.shutDown->targets.at(0).targetComponent.id, QStringLiteral("CameraEc1"));

    QVERIFY(p.activation && p.deactivation && p.resetting && p.initializing && p.finalizing);
    QVERIFY(!p.deactivation->targets.at(0).waitTime && !p.deactivation->targets.at(0).preceding);
    QVERIFY(p.resetting->targets.at(0).waitTime);
    QCOMPARE(p.resetting->targets.at(0).waitTime->waitTime, std::nullopt);
    QVERIFY(p.initializing->targets.at(0).preceding);
    QVERIFY(p.finalizing->targets.isEmpty());
    QCOMPARE(&*p.sequence(RtsSequenceKind::Activation), &*p.activation);
    QCOMPARE(&*p.sequence(RtsSequenceKind::Finalizing), &*p.finalizing);
}

void TestRtsXml::readsExtension()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    QCOMPARE(p.versionUpLogs,
             (QStringList {QStringLiteral("2024-01-02 created"),
                           QStringLiteral("2024-02-03 blur added")}));
    QCOMPARE(p.properties.size(), 1);
    QCOMPARE(p.properties.at(0).name, QStringLiteral("system.owner"));
    QCOMPARE(p.systems.size(), 2);
    QCOMPARE(p.systems.at(1).path, QStringLiteral("sub/Base.xml"));
}

void TestRtsXml::mapsLegacySpellings()
{
    const RtsProfile p = load(QStringLiteral("rts/legacy.xml"));
    QCOMPARE(p.abstract, std::nullopt);
    QCOMPARE(p.groups.size(), 1);
    QCOMPARE(p.groups.at(0).groupId, QStringLiteral("legacyGroup"));
    QCOMPARE(
        p.versionUpLogs,
        (QStringList {QStringLiteral("first"), QStringLiteral("second"), QStringLiteral("third")}));
    const RtsComponent *a = p.component(QStringLiteral("A0"));
    QVERIFY(a);
    QCOMPARE(a->isRequired, QStringLiteral("true"));
    QCOMPARE(a->visible, std::optional<QString>(QStringLiteral("true")));
    QCOMPARE(a->dataPorts.at(0).visible, std::optional<QString>(QStringLiteral("false")));
    QCOMPARE(a->layout->direction, QStringLiteral("RIGHT"));
    QCOMPARE(p.component(QStringLiteral("B0"))->isRequired, QStringLiteral("false"));
    QCOMPARE(p.component(QStringLiteral("B0"))->layout->direction, QStringLiteral("UP"));
    QCOMPARE(a->executionContexts.at(0).id, QStringLiteral("A0Ec1"));
    QCOMPARE(p.startUp->targets.at(0).targetComponent.componentId,
             QStringLiteral("RTC:Legacy.Test.A:1.0"));
    QCOMPARE(p.dataPortConnectors.at(0).source.portName, QStringLiteral("a_out"));
    QCOMPARE(p.dataPortConnectors.at(0).target.portName, QStringLiteral("b_in"));

    const QByteArray saved = writeRtsXml(p);
    QVERIFY(saved.contains("rts:groupId=\"legacyGroup\""));
    QVERIFY(!saved.contains("groupID"));
    QVERIFY(!saved.contains("VersionUpLog>"));
    QCOMPARE(saved.count("<rtsExt:VersionUpLogs>"), 3);
    QVERIFY(saved.contains("rtsExt:direction=\"RIGHT\""));
    QVERIFY(saved.contains("rts:isRequired=\"true\""));
    QVERIFY(!saved.contains("rts:abstract"));
}

void TestRtsXml::keepsUnknownContentInPlace()
{
    const RtsProfile p = load(QStringLiteral("rts/full.xml"));
    const QString future = QStringLiteral("urn:rtstudio:test:future");
    const RtsComponent &camera = p.components.at(0);
    QCOMPARE(camera.extras.attributes.size(), 1);
    QCOMPARE(camera.extras.children.size(), std::size_t(1));
    QCOMPARE(camera.extras.children.front().position, 5);

    Diagnostics diagnostics;
    const auto saved = parseXml(writeRtsXml(p), QStringLiteral("saved.xml"), &diagnostics);
    QVERIFY(saved);
    QCOMPARE(saved->attribute(future, QStringLiteral("rootFlag"))->value, QStringLiteral("kept"));
    const XmlNode *component = childAt(*saved, Ns::Rts, QStringLiteral("Components"));
    QVERIFY(component);
    QCOMPARE(component->attribute(future, QStringLiteral("componentFlag"))->value,
             QStringLiteral("yes"));
    QCOMPARE(indexOfChild(*component, future, QStringLiteral("Calibration")), 5);
    const XmlNode *calibration = &component->children.at(5);
    QCOMPARE(calibration->text, QStringLiteral("intrinsics"));
    QCOMPARE(calibration->attribute(future, QStringLiteral("file"))->value,
             QStringLiteral("camera.yml"));

    const XmlNode *connector = childAt(*saved, Ns::Rts, QStringLiteral("DataPortConnectors"));
    const XmlNode *target = childAt(*connector, Ns::Rts, QStringLiteral("targetDataPort"));
    QVERIFY(target);
    QCOMPARE(target->attribute(future, QStringLiteral("endFlag"))->value, QStringLiteral("target"));

    const int deployment = indexOfChild(*saved, future, QStringLiteral("Deployment"));
    QCOMPARE(deployment, int(saved->children.size()) - 1);
    QCOMPARE(saved->children.back().children.size(), std::size_t(1));
}

void TestRtsXml::keepsRootExtensionType()
{
    // rtsprofile may type the root rtsExt:rts_profile_ext (which makes its rtsExt: attributes
    // schema-valid); saving keeps it, and a root without one stays without.
    QByteArray file = readFile(dataPath(QStringLiteral("rts/full.xml")));
    QVERIFY(!file.contains("rts_profile_ext"));
    const auto plain = parseXml(writeRtsXml(load(QStringLiteral("rts/full.xml"))), QStringLiteral("saved.xml"), nullptr);
    QVERIFY(plain && plain->xsiTypeName.isEmpty());
    const int root = file.indexOf("<rts:RtsProfile ");
    QVERIFY(root >= 0);
    file.insert(root + int(qstrlen("<rts:RtsProfile ")), "xsi:type=\"rtsExt:rts_profile_ext\" ");
    Diagnostics diagnostics;
    const auto typed = readRtsXml(file, QStringLiteral("typed.xml"), &diagnostics);
    QVERIFY2(typed, qPrintable(diagnostics.isEmpty() ? QString() : diagnostics.first().toString()));
    const auto saved = parseXml(writeRtsXml(*typed), QStringLiteral("saved.xml"), nullptr);
    QVERIFY(saved);
    QCOMPARE(saved->xsiTypeNamespace, Ns::RtsExt);
    QCOMPARE(saved->xsiTypeName, QStringLiteral("rts_profile_ext"));
}

void TestRtsXml::writesSchemaFormWithXsiTypes()
{
    const QByteArray saved = writeRtsXml(load(QStringLiteral("rts/full.xml")));
    for (const char *type :
         {"component_ext", "dataport_ext", "serviceport_ext", "execution_context_ext",
          "target_component_ext", "dataport_connector_ext", "serviceport_connector_ext",
          "target_port_ext", "condition_ext"}) {
        QVERIFY2(saved.contains(QByteArray("xsi:type=\"rtsExt:") + type + '"'), type);
    }
    QVERIFY(saved.contains("xmlns:rts=\"http://www.openrtp.org/namespaces/rts\""));
    QVERIFY(saved.contains("xmlns:rtsExt=\"http://www.openrtp.org/namespaces/rts_ext\""));
    QVERIFY(saved.contains("rts:version=\"0.2\""));
    // In a condition, WaitTime/Preceding come before TargetComponent (schema order).
    const qsizetype wait = saved.indexOf("<rts:WaitTime rts:waitTime=\"100\"");
    const qsizetype target = saved.indexOf("<rts:TargetComponent", wait);
    QVERIFY(wait > 0 && target > wait);
}

void TestRtsXml::roundTrips_data()
{
    QTest::addColumn<QString>("name");
    const QDir dir(dataPath(QStringLiteral("rts")));
    for (const QString &file : dir.entryList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(file)) << QStringLiteral("rts/") + file;
}

void TestRtsXml::roundTrips()
{
    QFETCH(QString, name);
    const QByteArray input = readFile(dataPath(name));
    Diagnostics diagnostics;
    const auto profile = readRtsXml(input, name, &diagnostics);
    QVERIFY2(profile && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));

    const QByteArray saved = writeRtsXml(*profile);
    const auto again = readRtsXml(saved, QStringLiteral("saved.xml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY2(*again == *profile, saved.constData());
    QCOMPARE(writeRtsXml(*again), saved);

    const QString difference = xmlDifference(*parseXml(input, name, nullptr),
                                             *parseXml(saved, name, nullptr), rtsQuirks());
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestRtsXml::everyTableFieldRoundTrips()
{
    RtsProfile profile;
    RtsFiller filler;
    filler.fill(profile);
    // Every element type of the system is reached, each with several fields.
    QVERIFY2(filler.scalarCount() > 500, qPrintable(QString::number(filler.scalarCount())));
    QVERIFY(profile.startUp && profile.startUp->targets.at(1).preceding);

    Diagnostics diagnostics;
    const auto viaXml = readRtsXml(writeRtsXml(profile), QStringLiteral("table.xml"), &diagnostics);
    QVERIFY2(viaXml && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY(*viaXml == profile);

    const auto viaYaml
        = readRtsYaml(writeRtsYaml(profile), QStringLiteral("table.yaml"), &diagnostics);
    QVERIFY2(viaYaml && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY(*viaYaml == profile);
}

void TestRtsXml::editedModelSurvivesSaving()
{
    RtsProfile p = RtsProfile::createNew(QStringLiteral("Vendor"), QStringLiteral("New"),
                                         QStringLiteral("1.0"));
    QCOMPARE(p.id, QStringLiteral("RTSystem:Vendor:New:1.0"));
    QCOMPARE(p.version, QStringLiteral("0.2"));
    QVERIFY(QDateTime::fromString(p.creationDate, Qt::ISODate).isValid());
    QCOMPARE(p.updateDate, p.creationDate);
    QCOMPARE(p.abstract, std::nullopt);

    RtsComponent c;
    c.id = QStringLiteral("RTC:Vendor:cat:Comp:1.0");
    c.pathUri = QStringLiteral("localhost/Comp0.rtc");
    c.instanceName = QStringLiteral("Comp0");
    c.compositeType = QStringLiteral("None");
    c.comment = QString(); // present but empty: must stay distinct from absent
    c.layout = RtsLocation {QStringLiteral("1"),
                            QStringLiteral("2"),
                            QStringLiteral("-1"),
                            QStringLiteral("-1"),
                            QStringLiteral("RIGHT"),
                            {},
                            {},
                            {}};
    p.components.append(c);
    setRtsProperty(p.components.last().properties, QStringLiteral("IOR"), QStringLiteral("IOR:00"));
    setRtsProperty(p.components.last().properties, QStringLiteral("IOR"), QStringLiteral("IOR:01"));
    QCOMPARE(p.components.last().properties.size(), 1);

    Diagnostics diagnostics;
    const auto again = readRtsXml(writeRtsXml(p), QStringLiteral("new.xml"), &diagnostics);
    QVERIFY2(again && diagnostics.isEmpty(), qPrintable(joined(diagnostics)));
    QVERIFY(*again == p);
    QCOMPARE(again->components.at(0).comment, std::optional<QString>(QString()));
    QVERIFY(!again->components.at(0).visible);
    QCOMPARE(again->component(QStringLiteral("Comp0"))->properties.at(0).value,
             std::optional<QString>(QStringLiteral("IOR:01")));
}

void TestRtsXml::rejectsBrokenFiles_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("fragment");
    QTest::newRow("truncated") << "truncated.xml" << 9 << QString();
    QTest::newRow("wrong root") << "wrong-root.xml" << 2 << "expected <rts:RtsProfile>";
    QTest::newRow("wrong namespace")
        << "wrong-namespace.xml" << 2 << "http://www.openrtp.org/namespaces/rts'";
    QTest::newRow("invalid utf-8") << "invalid-utf8.xml" << 6 << "UTF-8";
    QTest::newRow("huge attribute") << "huge-attribute.xml" << 7 << "characters long";
    QTest::newRow("deep nesting") << "deep-nesting.xml" << 4 << "deeper than";
    QTest::newRow("not xml") << "not-xml.xml" << 1 << QString();
}

void TestRtsXml::rejectsBrokenFiles()
{
    QFETCH(QString, name);
    QFETCH(int, line);
    QFETCH(QString, fragment);
    const QString path = dataPath(QStringLiteral("rts-broken/") + name);
    const QByteArray data = readFile(path);
    QVERIFY2(!data.isEmpty(), qPrintable(path));
    Diagnostics diagnostics;
    const auto profile = readRtsXml(data, name, &diagnostics);
    QVERIFY(!profile);
    QVERIFY(hasErrors(diagnostics));
    const Diagnostic &first = diagnostics.first();
    QCOMPARE(first.file, name);
    QVERIFY2(first.line == line, qPrintable(first.toString()));
    QVERIFY2(first.message.contains(fragment), qPrintable(first.toString()));
    QVERIFY(first.toString().startsWith(QStringLiteral("%1:%2:").arg(name).arg(line)));
}

void TestRtsXml::reportsMissingRequiredParts()
{
    const QByteArray xml = R"(<?xml version="1.0"?>
<rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts"
    rts:id="RTSystem:v:n:1" rts:version="0.2" rts:updateDate="2024-01-01T00:00:00">
  <rts:Components rts:id="RTC:v:c:n:1" rts:pathUri="p" rts:isRequired="true"/>
  <rts:DataPortConnectors rts:connectorId="x" rts:name="x" rts:dataType="d"
      rts:interfaceType="i" rts:dataflowType="push"/>
  <rts:StartUp><rts:targets rts:sequence="1"/></rts:StartUp>
  <rts:Groups rts:groupId="g">stray text</rts:Groups>
</rts:RtsProfile>)";
    Diagnostics diagnostics;
    const auto profile = readRtsXml(xml, QStringLiteral("m.xml"), &diagnostics);
    QVERIFY(profile); // still understood: the editor can show and fix it
    const QString all = joined(diagnostics);
    QVERIFY2(all.contains(QStringLiteral("m.xml:2:1: error:"))
                 && all.contains(QStringLiteral("creationDate")),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("m.xml:4:"))
                 && all.contains(QStringLiteral("instanceName")),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("m.xml:5:"))
                 && all.contains(QStringLiteral("sourceDataPort"))
                 && all.contains(QStringLiteral("targetDataPort")),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("m.xml:7:"))
                 && all.contains(QStringLiteral("TargetComponent")),
             qPrintable(all));
    QVERIFY2(all.contains(QStringLiteral("m.xml:8:3: warning: text inside <Groups>")),
             qPrintable(all));
}

namespace {

RtsProfile largeSystem(int components, int connectors)
{
    RtsProfile p = RtsProfile::createNew(QStringLiteral("Bench"), QStringLiteral("Large"),
                                         QStringLiteral("1.0"));
    for (int i = 0; i < components; ++i) {
        RtsComponent c;
        c.instanceName = QStringLiteral("Comp%1").arg(i);
        c.id = QStringLiteral("RTC:Bench:cat:Comp%1:1.0").arg(i);
        c.pathUri = QStringLiteral("localhost/%1.rtc").arg(c.instanceName);
        c.compositeType = QStringLiteral("None");
        c.visible = QStringLiteral("true");
        for (const char *port : {"in", "out"}) {
            RtsPort dp;
            dp.name = c.instanceName + QLatin1Char('.') + QLatin1String(port);
            dp.visible = QStringLiteral("true");
            c.dataPorts.append(dp);
        }
        RtsExecutionContext ec;
        ec.id = QStringLiteral("0");
        ec.kind = QStringLiteral("PeriodicExecutionContext");
        ec.rate = QStringLiteral("1000.0");
        c.executionContexts.append(ec);
        c.layout = RtsLocation {QString::number(i % 40 * 100),
                                QString::number(i / 40 * 100),
                                QStringLiteral("-1"),
                                QStringLiteral("-1"),
                                QStringLiteral("RIGHT"),
                                {},
                                {},
                                {}};
        setRtsProperty(c.properties, QStringLiteral("COMPONENT_PATH_ID"), c.pathUri);
        p.components.append(c);
    }
    for (int i = 0; i < connectors; ++i) {
        const RtsComponent &from = p.components.at(i % components);
        const RtsComponent &to = p.components.at((i * 7 + 1) % components);
        RtsDataPortConnector c;
        c.connectorId = QStringLiteral("connector-%1").arg(i);
        c.name = QStringLiteral("out_in");
        c.dataType = QStringLiteral("IDL:RTC/TimedLong:1.0");
        c.interfaceType = QStringLiteral("corba_cdr");
        c.dataflowType = QStringLiteral("push");
        c.subscriptionType = QStringLiteral("flush");
        c.source.componentId = from.id;
        c.source.instanceName = from.instanceName;
        c.source.portName = from.dataPorts.at(1).name;
        c.target.componentId = to.id;
        c.target.instanceName = to.instanceName;
        c.target.portName = to.dataPorts.at(0).name;
        setRtsProperty(c.properties, QStringLiteral("dataport.buffer.length"), QStringLiteral("8"));
        p.dataPortConnectors.append(c);
    }
    return p;
}

} // namespace

void TestRtsXml::loadsAndSavesLargeSystems()
{
    const RtsProfile big = largeSystem(1000, 1500);
    QElapsedTimer timer;
    timer.start();
    const QByteArray saved = writeRtsXml(big);
    const qint64 saveMs = timer.restart();
    Diagnostics diagnostics;
    const auto loaded = readRtsXml(saved, QStringLiteral("large.xml"), &diagnostics);
    const qint64 loadMs = timer.elapsed();
    QVERIFY(loaded && diagnostics.isEmpty());
    QVERIFY(*loaded == big);
    // The times are for the reader of the log; bench_profile measures them against the goal.
    qInfo("1000 components, 1500 connectors, %lld KiB: save %lld ms, load %lld ms",
          qint64(saved.size() / 1024), saveMs, loadMs);
}

QTEST_GUILESS_MAIN(TestRtsXml)
#include "tst_rtsxml.moc"
