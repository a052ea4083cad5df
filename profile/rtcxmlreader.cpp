// SPDX-License-Identifier: MIT
#include "namespaces.h"
#include "rtcxml.h"
#include "rtcxmlinternal.h"

#include <QCoreApplication>

namespace Profile {

using namespace RtcXml;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcXml", text);
}

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

/// Reads one element's model; every function takes the element and the read context.
class Reader
{
public:
    explicit Reader(const ReadContext &context)
        : m_context(context)
    { }

    RtcProfile profile(const XmlNode &root) const;

private:
    NodeReader reader(const XmlNode &node) const
    {
        return NodeReader(node, m_context.fileName, m_context.diagnostics);
    }
    std::optional<QString> variableName(NodeReader &r) const;
    RtcProperties properties(NodeReader &r) const;
    std::optional<RtcConstraint> constraint(NodeReader &r) const;

    RtcBasicInfo basicInfo(const XmlNode &node) const;
    RtcBasicDoc basicDoc(const XmlNode &node) const;
    RtcActions actions(const XmlNode &node) const;
    RtcActionStatus actionStatus(const XmlNode &node) const;
    void configurationSet(const XmlNode &node, RtcProfile &profile) const;
    RtcConfiguration configuration(const XmlNode &node) const;
    RtcConfigurationDoc configurationDoc(const XmlNode &node) const;
    RtcDataPort dataPort(const XmlNode &node) const;
    RtcDataPortDoc dataPortDoc(const XmlNode &node) const;
    RtcEvent event(const XmlNode &node) const;
    RtcEventDoc eventDoc(const XmlNode &node) const;
    RtcServicePort servicePort(const XmlNode &node) const;
    RtcServicePortDoc servicePortDoc(const XmlNode &node) const;
    RtcServiceInterface serviceInterface(const XmlNode &node) const;
    RtcServiceInterfaceDoc serviceInterfaceDoc(const XmlNode &node) const;
    RtcTransMethod transMethod(const XmlNode &node) const;
    RtcLanguage language(const XmlNode &node) const;
    RtcTargetEnvironment target(const XmlNode &node) const;
    RtcLibrary library(const XmlNode &node) const;
    RtcParameter parameter(const XmlNode &node) const;

    ReadContext m_context;
};

/// Reads an optional child element with `read` into `target`.
template<typename T, typename F>
void readOptional(NodeReader &r, const QString &ns, const QString &name, std::optional<T> &target,
                  F read)
{
    if (const XmlNode *child = r.child(ns, name))
        target = read(*child);
}

std::optional<QString> Reader::variableName(NodeReader &r) const
{
    // 0.2+ writes rtcExt:variableName; the 0.1 templates wrote varname in either namespace.
    if (auto value = r.attribute(Ns::RtcExt, s("variableName"), {s("varname")}))
        return value;
    return r.attribute(Ns::Rtc, s("varname"));
}

RtcProperties Reader::properties(NodeReader &r) const
{
    RtcProperties result;
    for (const XmlNode *child : r.children(Ns::RtcExt, s("Properties")))
        result.append(readProperty(*child, m_context));
    return result;
}

std::optional<RtcConstraint> Reader::constraint(NodeReader &r) const
{
    if (const XmlNode *child = r.child(Ns::Rtc, s("Constraint")))
        return readConstraint(*child, m_context);
    return std::nullopt;
}

RtcProfile Reader::profile(const XmlNode &root) const
{
    NodeReader r = reader(root);
    RtcProfile p;
    p.location = root.location;
    p.id = requiredAttribute(r, Ns::Rtc, s("id"), p.missing);
    p.version = requiredAttribute(r, Ns::Rtc, s("version"), p.missing);
    if (const XmlNode *node = r.child(Ns::Rtc, s("BasicInfo")))
        p.basicInfo = basicInfo(*node);
    else
        reportMissingChild(r, s("BasicInfo"), p.missing);
    if (const XmlNode *node = r.child(Ns::Rtc, s("Actions")))
        p.actions = actions(*node);
    else
        reportMissingChild(r, s("Actions"), p.missing);
    if (const XmlNode *node = r.child(Ns::Rtc, s("ConfigurationSet")))
        configurationSet(*node, p);
    for (const XmlNode *node : r.children(Ns::Rtc, s("DataPorts")))
        p.dataPorts.append(dataPort(*node));
    for (const XmlNode *node : r.children(Ns::Rtc, s("ServicePorts")))
        p.servicePorts.append(servicePort(*node));
    for (const XmlNode *node : r.children(Ns::Rtc, s("Parameters")))
        p.parameters.append(parameter(*node));
    readOptional(r, Ns::Rtc, s("Language"), p.language,
                 [this](const XmlNode &n) { return language(n); });
    p.extras = r.extras();
    return p;
}

RtcBasicInfo Reader::basicInfo(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcBasicInfo b;
    b.location = node.location;
    b.name = requiredAttribute(r, Ns::Rtc, s("name"), b.missing);
    b.componentType = requiredAttribute(r, Ns::Rtc, s("componentType"), b.missing);
    b.activityType = requiredAttribute(r, Ns::Rtc, s("activityType"), b.missing);
    b.componentKind = requiredAttribute(r, Ns::Rtc, s("componentKind"), b.missing);
    b.rtcType = r.attribute(Ns::Rtc, s("rtcType"));
    b.category = requiredAttribute(r, Ns::Rtc, s("category"), b.missing);
    b.description = r.attribute(Ns::Rtc, s("description"));
    b.executionRate = r.attribute(Ns::Rtc, s("executionRate"));
    b.executionType = requiredAttribute(r, Ns::Rtc, s("executionType"), b.missing);
    b.maxInstances = r.attribute(Ns::Rtc, s("maxInstances"));
    b.vendor = requiredAttribute(r, Ns::Rtc, s("vendor"), b.missing);
    b.version = requiredAttribute(r, Ns::Rtc, s("version"), b.missing);
    b.abstractText = r.attribute(Ns::Rtc, s("abstract"));
    b.hardwareProfile = r.attribute(Ns::Rtc, s("hardwareProfile"));
    b.creationDate = requiredAttribute(r, Ns::Rtc, s("creationDate"), b.missing);
    b.updateDate = requiredAttribute(r, Ns::Rtc, s("updateDate"), b.missing);
    b.comment = r.attribute(Ns::RtcExt, s("comment"));
    b.saveProject = r.attribute(Ns::RtcExt, s("saveProject"));
    readOptional(r, Ns::RtcDoc, s("Doc"), b.doc, [this](const XmlNode &n) { return basicDoc(n); });
    // Old EMF-era files spell the element VersionUpLog.
    for (const QString &name : {s("VersionUpLogs"), s("VersionUpLog")}) {
        for (const XmlNode *child : r.children(Ns::RtcExt, name))
            b.versionUpLogs.append(simpleText(*child, m_context));
    }
    b.properties = properties(r);
    b.extras = r.extras();
    return b;
}

RtcBasicDoc Reader::basicDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcBasicDoc d;
    d.location = node.location;
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.inout = r.attribute(Ns::RtcDoc, s("inout"));
    d.algorithm = r.attribute(Ns::RtcDoc, s("algorithm"));
    d.creator = r.attribute(Ns::RtcDoc, s("creator"));
    d.license = r.attribute(Ns::RtcDoc, s("license"));
    d.reference = r.attribute(Ns::RtcDoc, s("reference"));
    d.extras = r.extras();
    return d;
}

RtcActions Reader::actions(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcActions a;
    a.location = node.location;
    for (RtcAction action : rtcAllActions()) {
        if (const XmlNode *child = r.child(Ns::Rtc, rtcActionElementName(action)))
            a[action] = actionStatus(*child);
    }
    a.extras = r.extras();
    return a;
}

RtcActionStatus Reader::actionStatus(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcActionStatus a;
    a.location = node.location;
    a.implemented = normalizedBoolean(requiredAttribute(r, Ns::Rtc, s("implemented"), a.missing));
    readOptional(r, Ns::RtcDoc, s("Doc"), a.doc, [this](const XmlNode &n) {
        NodeReader dr = reader(n);
        RtcActionDoc d;
        d.location = n.location;
        d.description = dr.attribute(Ns::RtcDoc, s("description"));
        d.preCondition = dr.attribute(Ns::RtcDoc, s("preCondition"));
        d.postCondition = dr.attribute(Ns::RtcDoc, s("postCondition"));
        d.extras = dr.extras();
        return d;
    });
    a.extras = r.extras();
    return a;
}

void Reader::configurationSet(const XmlNode &node, RtcProfile &profile) const
{
    NodeReader r = reader(node);
    profile.configurationSetLocation = node.location;
    for (const XmlNode *child : r.children(Ns::Rtc, s("Configuration")))
        profile.configurations.append(configuration(*child));
    profile.hasConfigurationSet = profile.configurations.isEmpty();
    profile.configurationSetExtras = r.extras();
}

RtcConfiguration Reader::configuration(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcConfiguration c;
    c.location = node.location;
    c.name = requiredAttribute(r, Ns::Rtc, s("name"), c.missing);
    c.type = requiredAttribute(r, Ns::Rtc, s("type"), c.missing);
    c.defaultValue = requiredAttribute(r, Ns::Rtc, s("defaultValue"), c.missing);
    c.unit = r.attribute(Ns::Rtc, s("unit"));
    c.variableName = variableName(r);
    c.comment = r.attribute(Ns::RtcExt, s("comment"));
    c.constraint = constraint(r);
    readOptional(r, Ns::RtcDoc, s("Doc"), c.doc,
                 [this](const XmlNode &n) { return configurationDoc(n); });
    c.properties = properties(r);
    c.extras = r.extras();
    return c;
}

RtcConfigurationDoc Reader::configurationDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcConfigurationDoc d;
    d.location = node.location;
    d.dataname = r.attribute(Ns::RtcDoc, s("dataname"));
    d.defaultValue = r.attribute(Ns::RtcDoc, s("defaultValue"));
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.unit = r.attribute(Ns::RtcDoc, s("unit"));
    d.range = r.attribute(Ns::RtcDoc, s("range"));
    d.constraint = r.attribute(Ns::RtcDoc, s("constraint"));
    d.extras = r.extras();
    return d;
}

RtcDataPort Reader::dataPort(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcDataPort p;
    p.location = node.location;
    p.portType = requiredAttribute(r, Ns::Rtc, s("portType"), p.missing);
    p.name = requiredAttribute(r, Ns::Rtc, s("name"), p.missing);
    p.type = requiredAttribute(r, Ns::Rtc, s("type"), p.missing);
    p.idlFile = r.attribute(Ns::Rtc, s("idlFile"));
    p.interfaceType = r.attribute(Ns::Rtc, s("interfaceType"));
    p.dataflowType = r.attribute(Ns::Rtc, s("dataflowType"));
    p.subscriptionType = r.attribute(Ns::Rtc, s("subscriptionType"), {s("subscriprionType")});
    p.unit = r.attribute(Ns::Rtc, s("unit"));
    p.position = normalizedPosition(requiredAttribute(r, Ns::RtcExt, s("position"), p.missing));
    p.variableName = variableName(r);
    p.comment = r.attribute(Ns::RtcExt, s("comment"));
    p.constraint = constraint(r);
    for (const XmlNode *child : r.children(Ns::Rtc, s("Event")))
        p.events.append(event(*child));
    readOptional(r, Ns::RtcDoc, s("Doc"), p.doc,
                 [this](const XmlNode &n) { return dataPortDoc(n); });
    p.properties = properties(r);
    p.extras = r.extras();
    return p;
}

RtcDataPortDoc Reader::dataPortDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcDataPortDoc d;
    d.location = node.location;
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.type = r.attribute(Ns::RtcDoc, s("type"));
    d.number = r.attribute(Ns::RtcDoc, s("number"));
    d.semantics = r.attribute(Ns::RtcDoc, s("semantics"));
    d.unit = r.attribute(Ns::RtcDoc, s("unit"));
    d.occerrence = r.attribute(Ns::RtcDoc, s("occerrence"));
    d.operation = r.attribute(Ns::RtcDoc, s("operation"));
    d.extras = r.extras();
    return d;
}

RtcEvent Reader::event(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcEvent e;
    e.location = node.location;
    e.name = requiredAttribute(r, Ns::Rtc, s("name"), e.missing);
    e.condition = r.attribute(Ns::Rtc, s("condition"));
    e.source = requiredAttribute(r, Ns::Rtc, s("source"), e.missing);
    e.target = requiredAttribute(r, Ns::Rtc, s("target"), e.missing);
    e.type = r.attribute(Ns::Rtc, s("type"));
    readOptional(r, Ns::RtcDoc, s("Doc"), e.doc, [this](const XmlNode &n) { return eventDoc(n); });
    e.extras = r.extras();
    return e;
}

RtcEventDoc Reader::eventDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcEventDoc d;
    d.location = node.location;
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.type = r.attribute(Ns::RtcDoc, s("type"));
    d.number = r.attribute(Ns::RtcDoc, s("number"));
    d.semantics = r.attribute(Ns::RtcDoc, s("semantics"));
    d.unit = r.attribute(Ns::RtcDoc, s("unit"));
    d.operation = r.attribute(Ns::RtcDoc, s("operation"));
    d.extras = r.extras();
    return d;
}

RtcServicePort Reader::servicePort(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcServicePort p;
    p.location = node.location;
    p.name = requiredAttribute(r, Ns::Rtc, s("name"), p.missing);
    p.position = normalizedPosition(requiredAttribute(r, Ns::RtcExt, s("position"), p.missing));
    p.comment = r.attribute(Ns::RtcExt, s("comment"));
    for (const XmlNode *child : r.children(Ns::Rtc, s("ServiceInterface")))
        p.interfaces.append(serviceInterface(*child));
    for (const XmlNode *child : r.children(Ns::Rtc, s("TransMethods")))
        p.transMethods.append(transMethod(*child));
    readOptional(r, Ns::RtcDoc, s("Doc"), p.doc,
                 [this](const XmlNode &n) { return servicePortDoc(n); });
    p.properties = properties(r);
    p.extras = r.extras();
    return p;
}

RtcServicePortDoc Reader::servicePortDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcServicePortDoc d;
    d.location = node.location;
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.ifdescription = r.attribute(Ns::RtcDoc, s("ifdescription"));
    d.extras = r.extras();
    return d;
}

RtcServiceInterface Reader::serviceInterface(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcServiceInterface i;
    i.location = node.location;
    i.name = requiredAttribute(r, Ns::Rtc, s("name"), i.missing);
    i.direction = requiredAttribute(r, Ns::Rtc, s("direction"), i.missing);
    i.instanceName = r.attribute(Ns::Rtc, s("instanceName"));
    i.idlFile = r.attribute(Ns::Rtc, s("idlFile"));
    i.type = requiredAttribute(r, Ns::Rtc, s("type"), i.missing);
    i.path = r.attribute(Ns::Rtc, s("path"));
    i.variableName = variableName(r);
    i.comment = r.attribute(Ns::RtcExt, s("comment"));
    readOptional(r, Ns::RtcDoc, s("Doc"), i.doc,
                 [this](const XmlNode &n) { return serviceInterfaceDoc(n); });
    i.properties = properties(r);
    i.extras = r.extras();
    return i;
}

RtcServiceInterfaceDoc Reader::serviceInterfaceDoc(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcServiceInterfaceDoc d;
    d.location = node.location;
    d.description = r.attribute(Ns::RtcDoc, s("description"));
    d.docArgument = r.attribute(Ns::RtcDoc, s("docArgument"));
    d.docReturn = r.attribute(Ns::RtcDoc, s("docReturn"));
    d.docException = r.attribute(Ns::RtcDoc, s("docException"));
    d.docPreCondition = r.attribute(Ns::RtcDoc, s("docPreCondition"));
    d.docPostCondition = r.attribute(Ns::RtcDoc, s("docPostCondition"));
    d.extras = r.extras();
    return d;
}

RtcTransMethod Reader::transMethod(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcTransMethod t;
    t.location = node.location;
    t.kind = requiredAttribute(r, Ns::Rtc, s("kind"), t.missing);
    t.extras = r.extras();
    return t;
}

RtcLanguage Reader::language(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcLanguage l;
    l.location = node.location;
    l.kind = requiredAttribute(r, Ns::Rtc, s("kind"), l.missing);
    for (const XmlNode *child : r.children(Ns::RtcExt, s("targets")))
        l.targets.append(target(*child));
    l.properties = properties(r);
    l.extras = r.extras();
    return l;
}

RtcTargetEnvironment Reader::target(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcTargetEnvironment t;
    t.location = node.location;
    t.langVersion = r.attribute(Ns::RtcExt, s("langVersion"));
    t.os = r.attribute(Ns::RtcExt, s("os"));
    t.other = r.attribute(Ns::RtcExt, s("other"));
    t.cpuOther = r.attribute(Ns::RtcExt, s("cpuOther"));
    for (const XmlNode *child : r.children(Ns::RtcExt, s("osVersions")))
        t.osVersions.append(simpleText(*child, m_context));
    for (const XmlNode *child : r.children(Ns::RtcExt, s("cpus")))
        t.cpus.append(simpleText(*child, m_context));
    for (const XmlNode *child : r.children(Ns::RtcExt, s("libraries")))
        t.libraries.append(library(*child));
    t.extras = r.extras();
    return t;
}

RtcLibrary Reader::library(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcLibrary l;
    l.location = node.location;
    l.name = requiredAttribute(r, Ns::RtcExt, s("name"), l.missing);
    l.version = r.attribute(Ns::RtcExt, s("version"));
    l.other = r.attribute(Ns::RtcExt, s("other"));
    l.extras = r.extras();
    return l;
}

RtcParameter Reader::parameter(const XmlNode &node) const
{
    NodeReader r = reader(node);
    RtcParameter p;
    p.location = node.location;
    p.name = requiredAttribute(r, Ns::Rtc, s("name"), p.missing);
    p.defaultValue = r.attribute(Ns::Rtc, s("defaultValue"));
    p.extras = r.extras();
    return p;
}

/// Explains why a root element is not an RTC Profile; empty when it is one.
QString rootProblem(const XmlNode &root)
{
    if (root.name != QLatin1String("RtcProfile")) {
        return tr("the root element is <%1>, not <rtc:RtcProfile>: this is not an RTC Profile")
            .arg(root.name);
    }
    if (root.namespaceUri != Ns::Rtc) {
        return tr("<RtcProfile> is in the namespace '%1' instead of '%2'")
            .arg(root.namespaceUri.isEmpty() ? tr("(none)") : root.namespaceUri, Ns::Rtc);
    }
    return {};
}

} // namespace

std::optional<RtcProfile> readRtcXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics)
{
    Diagnostics local;
    Diagnostics *sink = diagnostics ? diagnostics : &local;
    const std::optional<XmlNode> root = parseXml(data, fileName, sink);
    if (!root)
        return std::nullopt;
    const QString problem = rootProblem(*root);
    if (!problem.isEmpty()) {
        sink->append(
            Diagnostic::error(fileName, root->location.line, root->location.column, problem));
        return std::nullopt;
    }
    return Reader(ReadContext {fileName, sink}).profile(*root);
}

} // namespace Profile
