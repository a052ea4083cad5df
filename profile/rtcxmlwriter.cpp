// SPDX-License-Identifier: MIT
#include "namespaces.h"
#include "rtcxml.h"
#include "rtcxmlinternal.h"

namespace Profile {

namespace RtcXml {

namespace {

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

XmlNode element(const QString &ns, const QString &name)
{
    XmlNode node(ns, name);
    node.prefix = Ns::preferredPrefix(ns);
    return node;
}

/// An element with OpenRTP's extended type, e.g. `xsi:type="rtcExt:dataport_ext"`.
XmlNode typedElement(const QString &name, const QString &typeNs, const char *typeName)
{
    XmlNode node = element(Ns::Rtc, name);
    node.setXsiType(typeNs, s(typeName));
    return node;
}

void addProperties(XmlNode &node, const RtcProperties &properties)
{
    for (const RtcProperty &property : properties)
        node.addChild(propertyToXml(property));
}

template<typename T> void addOptional(XmlNode &node, const std::optional<T> &value)
{
    if (value)
        node.addChild(toXml(*value));
}

void addTexts(XmlNode &node, const QString &ns, const QString &name, const QStringList &texts)
{
    for (const QString &text : texts)
        node.addChild(textElement(ns, name, text));
}

} // namespace

XmlNode toXml(const RtcBasicDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("inout"), d.inout);
    node.setAttribute(Ns::RtcDoc, s("algorithm"), d.algorithm);
    node.setAttribute(Ns::RtcDoc, s("creator"), d.creator);
    node.setAttribute(Ns::RtcDoc, s("license"), d.license);
    node.setAttribute(Ns::RtcDoc, s("reference"), d.reference);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcBasicInfo &b)
{
    XmlNode node = typedElement(s("BasicInfo"), Ns::RtcExt, "basic_info_ext");
    const RtcMissing &m = b.missing;
    setRequired(node, Ns::Rtc, s("name"), b.name, m);
    setRequired(node, Ns::Rtc, s("componentType"), b.componentType, m);
    setRequired(node, Ns::Rtc, s("activityType"), b.activityType, m);
    setRequired(node, Ns::Rtc, s("componentKind"), b.componentKind, m);
    node.setAttribute(Ns::Rtc, s("rtcType"), b.rtcType);
    setRequired(node, Ns::Rtc, s("category"), b.category, m);
    node.setAttribute(Ns::Rtc, s("description"), b.description);
    node.setAttribute(Ns::Rtc, s("executionRate"), b.executionRate);
    setRequired(node, Ns::Rtc, s("executionType"), b.executionType, m);
    node.setAttribute(Ns::Rtc, s("maxInstances"), b.maxInstances);
    setRequired(node, Ns::Rtc, s("vendor"), b.vendor, m);
    setRequired(node, Ns::Rtc, s("version"), b.version, m);
    node.setAttribute(Ns::Rtc, s("abstract"), b.abstractText);
    node.setAttribute(Ns::Rtc, s("hardwareProfile"), b.hardwareProfile);
    setRequired(node, Ns::Rtc, s("creationDate"), b.creationDate, m);
    setRequired(node, Ns::Rtc, s("updateDate"), b.updateDate, m);
    node.setAttribute(Ns::RtcExt, s("comment"), b.comment);
    node.setAttribute(Ns::RtcExt, s("saveProject"), b.saveProject);
    addOptional(node, b.doc);
    addTexts(node, Ns::RtcExt, s("VersionUpLogs"), b.versionUpLogs);
    addProperties(node, b.properties);
    b.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcActionDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("preCondition"), d.preCondition);
    node.setAttribute(Ns::RtcDoc, s("postCondition"), d.postCondition);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(RtcAction action, const RtcActionStatus &a)
{
    XmlNode node = typedElement(rtcActionElementName(action), Ns::RtcDoc, "action_status_doc");
    setRequired(node, Ns::Rtc, s("implemented"), normalizedBoolean(a.implemented), a.missing);
    addOptional(node, a.doc);
    a.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcActions &actions)
{
    XmlNode node = element(Ns::Rtc, s("Actions"));
    for (RtcAction action : rtcAllActions()) {
        if (const auto &status = actions[action])
            node.addChild(toXml(action, *status));
    }
    actions.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcConfigurationDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("dataname"), d.dataname);
    node.setAttribute(Ns::RtcDoc, s("defaultValue"), d.defaultValue);
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("unit"), d.unit);
    node.setAttribute(Ns::RtcDoc, s("range"), d.range);
    node.setAttribute(Ns::RtcDoc, s("constraint"), d.constraint);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcConfiguration &c)
{
    XmlNode node = typedElement(s("Configuration"), Ns::RtcExt, "configuration_ext");
    setRequired(node, Ns::Rtc, s("name"), c.name, c.missing);
    setRequired(node, Ns::Rtc, s("type"), c.type, c.missing);
    setRequired(node, Ns::Rtc, s("defaultValue"), c.defaultValue, c.missing);
    node.setAttribute(Ns::Rtc, s("unit"), c.unit);
    node.setAttribute(Ns::RtcExt, s("variableName"), c.variableName);
    node.setAttribute(Ns::RtcExt, s("comment"), c.comment);
    if (c.constraint)
        node.addChild(constraintToXml(*c.constraint));
    addOptional(node, c.doc);
    addProperties(node, c.properties);
    // Files of RTC Builder's older versions type plain configurations rtcDoc:configuration_doc;
    // the extension type is needed only for the extension's fields.
    if (c.extras.hasXsiType(Ns::RtcDoc, s("configuration_doc")) && !c.variableName && !c.comment
        && c.properties.isEmpty())
        node.setXsiType(Ns::RtcDoc, s("configuration_doc"));
    c.extras.applyTo(node);
    return node;
}

XmlNode configurationSetToXml(const RtcProfile &profile)
{
    XmlNode node = element(Ns::Rtc, s("ConfigurationSet"));
    for (const RtcConfiguration &configuration : profile.configurations)
        node.addChild(toXml(configuration));
    profile.configurationSetExtras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcDataPortDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("type"), d.type);
    node.setAttribute(Ns::RtcDoc, s("number"), d.number);
    node.setAttribute(Ns::RtcDoc, s("semantics"), d.semantics);
    node.setAttribute(Ns::RtcDoc, s("unit"), d.unit);
    node.setAttribute(Ns::RtcDoc, s("occerrence"), d.occerrence);
    node.setAttribute(Ns::RtcDoc, s("operation"), d.operation);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcEventDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("type"), d.type);
    node.setAttribute(Ns::RtcDoc, s("number"), d.number);
    node.setAttribute(Ns::RtcDoc, s("semantics"), d.semantics);
    node.setAttribute(Ns::RtcDoc, s("unit"), d.unit);
    node.setAttribute(Ns::RtcDoc, s("operation"), d.operation);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcEvent &e)
{
    XmlNode node = typedElement(s("Event"), Ns::RtcDoc, "event_doc");
    setRequired(node, Ns::Rtc, s("name"), e.name, e.missing);
    node.setAttribute(Ns::Rtc, s("condition"), e.condition);
    setRequired(node, Ns::Rtc, s("source"), e.source, e.missing);
    setRequired(node, Ns::Rtc, s("target"), e.target, e.missing);
    node.setAttribute(Ns::Rtc, s("type"), e.type);
    addOptional(node, e.doc);
    e.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcDataPort &p)
{
    XmlNode node = typedElement(s("DataPorts"), Ns::RtcExt, "dataport_ext");
    setRequired(node, Ns::Rtc, s("portType"), p.portType, p.missing);
    setRequired(node, Ns::Rtc, s("name"), p.name, p.missing);
    setRequired(node, Ns::Rtc, s("type"), p.type, p.missing);
    node.setAttribute(Ns::Rtc, s("idlFile"), p.idlFile);
    node.setAttribute(Ns::Rtc, s("interfaceType"), p.interfaceType);
    node.setAttribute(Ns::Rtc, s("dataflowType"), p.dataflowType);
    node.setAttribute(Ns::Rtc, s("subscriptionType"), p.subscriptionType);
    node.setAttribute(Ns::Rtc, s("unit"), p.unit);
    setRequired(node, Ns::RtcExt, s("position"), p.position, p.missing);
    node.setAttribute(Ns::RtcExt, s("variableName"), p.variableName);
    node.setAttribute(Ns::RtcExt, s("comment"), p.comment);
    if (p.constraint)
        node.addChild(constraintToXml(*p.constraint));
    for (const RtcEvent &event : p.events)
        node.addChild(toXml(event));
    addOptional(node, p.doc);
    addProperties(node, p.properties);
    p.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcServiceInterfaceDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("docArgument"), d.docArgument);
    node.setAttribute(Ns::RtcDoc, s("docReturn"), d.docReturn);
    node.setAttribute(Ns::RtcDoc, s("docException"), d.docException);
    node.setAttribute(Ns::RtcDoc, s("docPreCondition"), d.docPreCondition);
    node.setAttribute(Ns::RtcDoc, s("docPostCondition"), d.docPostCondition);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcServiceInterface &i)
{
    XmlNode node = typedElement(s("ServiceInterface"), Ns::RtcExt, "serviceinterface_ext");
    setRequired(node, Ns::Rtc, s("name"), i.name, i.missing);
    setRequired(node, Ns::Rtc, s("direction"), i.direction, i.missing);
    node.setAttribute(Ns::Rtc, s("instanceName"), i.instanceName);
    node.setAttribute(Ns::Rtc, s("idlFile"), i.idlFile);
    setRequired(node, Ns::Rtc, s("type"), i.type, i.missing);
    node.setAttribute(Ns::Rtc, s("path"), i.path);
    node.setAttribute(Ns::RtcExt, s("variableName"), i.variableName);
    node.setAttribute(Ns::RtcExt, s("comment"), i.comment);
    addOptional(node, i.doc);
    addProperties(node, i.properties);
    i.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcTransMethod &t)
{
    XmlNode node = element(Ns::Rtc, s("TransMethods"));
    setRequired(node, Ns::Rtc, s("kind"), t.kind, t.missing);
    t.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcServicePortDoc &d)
{
    XmlNode node = element(Ns::RtcDoc, s("Doc"));
    node.setAttribute(Ns::RtcDoc, s("description"), d.description);
    node.setAttribute(Ns::RtcDoc, s("ifdescription"), d.ifdescription);
    d.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcServicePort &p)
{
    XmlNode node = typedElement(s("ServicePorts"), Ns::RtcExt, "serviceport_ext");
    setRequired(node, Ns::Rtc, s("name"), p.name, p.missing);
    setRequired(node, Ns::RtcExt, s("position"), p.position, p.missing);
    node.setAttribute(Ns::RtcExt, s("comment"), p.comment);
    for (const RtcServiceInterface &interface : p.interfaces)
        node.addChild(toXml(interface));
    for (const RtcTransMethod &method : p.transMethods)
        node.addChild(toXml(method));
    addOptional(node, p.doc);
    addProperties(node, p.properties);
    p.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcLibrary &l)
{
    XmlNode node = element(Ns::RtcExt, s("libraries"));
    setRequired(node, Ns::RtcExt, s("name"), l.name, l.missing);
    node.setAttribute(Ns::RtcExt, s("version"), l.version);
    node.setAttribute(Ns::RtcExt, s("other"), l.other);
    l.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcTargetEnvironment &t)
{
    XmlNode node = element(Ns::RtcExt, s("targets"));
    node.setAttribute(Ns::RtcExt, s("langVersion"), t.langVersion);
    node.setAttribute(Ns::RtcExt, s("os"), t.os);
    node.setAttribute(Ns::RtcExt, s("other"), t.other);
    node.setAttribute(Ns::RtcExt, s("cpuOther"), t.cpuOther);
    addTexts(node, Ns::RtcExt, s("osVersions"), t.osVersions);
    addTexts(node, Ns::RtcExt, s("cpus"), t.cpus);
    for (const RtcLibrary &library : t.libraries)
        node.addChild(toXml(library));
    t.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcLanguage &l)
{
    XmlNode node = typedElement(s("Language"), Ns::RtcExt, "language_ext");
    setRequired(node, Ns::Rtc, s("kind"), l.kind, l.missing);
    for (const RtcTargetEnvironment &target : l.targets)
        node.addChild(toXml(target));
    addProperties(node, l.properties);
    l.extras.applyTo(node);
    return node;
}

XmlNode toXml(const RtcParameter &p)
{
    XmlNode node = element(Ns::Rtc, s("Parameters"));
    setRequired(node, Ns::Rtc, s("name"), p.name, p.missing);
    node.setAttribute(Ns::Rtc, s("defaultValue"), p.defaultValue);
    p.extras.applyTo(node);
    return node;
}

} // namespace RtcXml

XmlNode rtcProfileToXml(const RtcProfile &profile)
{
    using namespace RtcXml;
    XmlNode root = element(Ns::Rtc, s("RtcProfile"));
    setRequired(root, Ns::Rtc, s("id"), profile.id, profile.missing);
    // Saving upgrades the file to the current format, as RTC Builder does.
    root.setAttribute(Ns::Rtc, s("version"), RtcProfile::CurrentVersion);
    const bool basicInfoAbsent
        = profile.missing.contains(s("BasicInfo")) && profile.basicInfo == RtcBasicInfo();
    if (!basicInfoAbsent)
        root.addChild(toXml(profile.basicInfo));
    if (!profile.missing.contains(s("Actions")) || profile.actions != RtcActions())
        root.addChild(toXml(profile.actions));
    if (profile.hasConfigurationSet || !profile.configurations.isEmpty()
        || !profile.configurationSetExtras.isEmpty())
        root.addChild(configurationSetToXml(profile));
    for (const RtcDataPort &port : profile.dataPorts)
        root.addChild(toXml(port));
    for (const RtcServicePort &port : profile.servicePorts)
        root.addChild(toXml(port));
    for (const RtcParameter &parameter : profile.parameters)
        root.addChild(toXml(parameter));
    if (profile.language)
        root.addChild(toXml(*profile.language));
    profile.extras.applyTo(root);
    return root;
}

QByteArray writeRtcXml(const RtcProfile &profile)
{
    return serializeXml(rtcProfileToXml(profile));
}

} // namespace Profile
