// SPDX-License-Identifier: MIT
// Builds the XmlNode tree of an RtsProfile in schema order with OpenRTP's xsi:types; the extras
// of each element are put back at the positions they were read from.
#include "namespaces.h"
#include "rtsxml.h"

namespace Profile {

namespace {

QString n(const char *name)
{
    return QString::fromLatin1(name);
}

void writeProperties(XmlNode &parent, const RtsProperties &properties)
{
    for (const RtsProperty &p : properties) {
        XmlNode &node = parent.addChild(Ns::RtsExt, n("Properties"));
        node.setAttribute(Ns::RtsExt, n("name"), p.name);
        node.setAttribute(Ns::RtsExt, n("value"), p.value);
        p.extras.applyTo(node);
    }
}

void writeTargetBase(XmlNode &node, const RtsTargetComponent &t)
{
    node.setAttribute(Ns::Rts, n("componentId"), t.componentId);
    node.setAttribute(Ns::Rts, n("instanceName"), t.instanceName);
}

void writeTargetComponent(XmlNode &parent, const char *name, const RtsTargetComponent &t)
{
    XmlNode &node = parent.addChild(Ns::Rts, n(name));
    node.setXsiType(Ns::RtsExt, n("target_component_ext"));
    writeTargetBase(node, t);
    writeProperties(node, t.properties);
    t.extras.applyTo(node);
}

void writeTargetPort(XmlNode &parent, const char *name, const RtsTargetPort &t)
{
    XmlNode &node = parent.addChild(Ns::Rts, n(name));
    node.setXsiType(Ns::RtsExt, n("target_port_ext"));
    writeTargetBase(node, t);
    node.setAttribute(Ns::Rts, n("portName"), t.portName);
    writeProperties(node, t.properties);
    t.extras.applyTo(node);
}

void writeTargetExecutionContext(XmlNode &parent, const char *name,
                                 const RtsTargetExecutionContext &t)
{
    // target_executioncontext has no ext type in the schema, hence no xsi:type.
    XmlNode &node = parent.addChild(Ns::Rts, n(name));
    writeTargetBase(node, t);
    node.setAttribute(Ns::Rts, n("id"), t.id);
    writeProperties(node, t.properties);
    t.extras.applyTo(node);
}

void writePort(XmlNode &parent, const char *name, const char *xsiType, const RtsPort &port)
{
    XmlNode &node = parent.addChild(Ns::Rts, n(name));
    node.setXsiType(Ns::RtsExt, n(xsiType));
    node.setAttribute(Ns::Rts, n("name"), port.name);
    node.setAttribute(Ns::RtsExt, n("comment"), port.comment);
    node.setAttribute(Ns::RtsExt, n("visible"), port.visible);
    writeProperties(node, port.properties);
    port.extras.applyTo(node);
}

void writeConfigurationSet(XmlNode &parent, const RtsConfigurationSet &set)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("ConfigurationSets"));
    node.setAttribute(Ns::Rts, n("id"), set.id);
    for (const RtsConfigurationData &data : set.data) {
        XmlNode &child = node.addChild(Ns::Rts, n("ConfigurationData"));
        child.setAttribute(Ns::Rts, n("name"), data.name);
        child.setAttribute(Ns::Rts, n("data"), data.data);
        data.extras.applyTo(child);
    }
    set.extras.applyTo(node);
}

void writeExecutionContext(XmlNode &parent, const RtsExecutionContext &ec)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("ExecutionContexts"));
    node.setXsiType(Ns::RtsExt, n("execution_context_ext"));
    node.setAttribute(Ns::Rts, n("id"), ec.id);
    node.setAttribute(Ns::Rts, n("kind"), ec.kind);
    node.setAttribute(Ns::Rts, n("rate"), ec.rate);
    for (const RtsTargetComponent &participant : ec.participants)
        writeTargetComponent(node, "Participants", participant);
    writeProperties(node, ec.properties);
    ec.extras.applyTo(node);
}

void writeLocation(XmlNode &parent, const RtsLocation &l)
{
    XmlNode &node = parent.addChild(Ns::RtsExt, n("Location"));
    node.setAttribute(Ns::RtsExt, n("x"), l.x);
    node.setAttribute(Ns::RtsExt, n("y"), l.y);
    node.setAttribute(Ns::RtsExt, n("height"), l.height);
    node.setAttribute(Ns::RtsExt, n("width"), l.width);
    node.setAttribute(Ns::RtsExt, n("direction"), l.direction);
    l.extras.applyTo(node);
}

void writeComponentAttributes(XmlNode &node, const RtsComponent &c)
{
    node.setAttribute(Ns::Rts, n("id"), c.id);
    node.setAttribute(Ns::Rts, n("pathUri"), c.pathUri);
    node.setAttribute(Ns::Rts, n("instanceName"), c.instanceName);
    node.setAttribute(Ns::Rts, n("activeConfigurationSet"), c.activeConfigurationSet);
    node.setAttribute(Ns::Rts, n("compositeType"), c.compositeType);
    node.setAttribute(Ns::Rts, n("isRequired"), c.isRequired);
    node.setAttribute(Ns::RtsExt, n("comment"), c.comment);
    node.setAttribute(Ns::RtsExt, n("visible"), c.visible);
}

void writeComponent(XmlNode &parent, const RtsComponent &c)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("Components"));
    node.setXsiType(Ns::RtsExt, n("component_ext"));
    writeComponentAttributes(node, c);
    for (const RtsPort &port : c.dataPorts)
        writePort(node, "DataPorts", "dataport_ext", port);
    for (const RtsPort &port : c.servicePorts)
        writePort(node, "ServicePorts", "serviceport_ext", port);
    for (const RtsConfigurationSet &set : c.configurationSets)
        writeConfigurationSet(node, set);
    for (const RtsExecutionContext &ec : c.executionContexts)
        writeExecutionContext(node, ec);
    for (const RtsParticipant &participant : c.participants) {
        XmlNode &wrapper = node.addChild(Ns::Rts, n("Participants"));
        writeTargetComponent(wrapper, "Participant", participant.participant);
        participant.extras.applyTo(wrapper);
    }
    if (c.layout)
        writeLocation(node, *c.layout);
    writeProperties(node, c.properties);
    c.extras.applyTo(node);
}

void writeGroup(XmlNode &parent, const RtsGroup &g)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("Groups"));
    node.setAttribute(Ns::Rts, n("groupId"), g.groupId);
    for (const RtsTargetComponent &member : g.members)
        writeTargetComponent(node, "Members", member);
    g.extras.applyTo(node);
}

XmlNode &writeConnectorBase(XmlNode &parent, const char *name, const char *xsiType,
                            const RtsPortConnector &c)
{
    XmlNode &node = parent.addChild(Ns::Rts, n(name));
    node.setXsiType(Ns::RtsExt, n(xsiType));
    node.setAttribute(Ns::Rts, n("connectorId"), c.connectorId);
    node.setAttribute(Ns::Rts, n("name"), c.name);
    return node;
}

void writeConnectorExtension(XmlNode &node, const RtsPortConnector &c)
{
    node.setAttribute(Ns::RtsExt, n("comment"), c.comment);
    node.setAttribute(Ns::RtsExt, n("visible"), c.visible);
}

void writeDataPortConnector(XmlNode &parent, const RtsDataPortConnector &c)
{
    XmlNode &node = writeConnectorBase(parent, "DataPortConnectors", "dataport_connector_ext", c);
    node.setAttribute(Ns::Rts, n("dataType"), c.dataType);
    node.setAttribute(Ns::Rts, n("interfaceType"), c.interfaceType);
    node.setAttribute(Ns::Rts, n("dataflowType"), c.dataflowType);
    node.setAttribute(Ns::Rts, n("subscriptionType"), c.subscriptionType);
    node.setAttribute(Ns::Rts, n("pushInterval"), c.pushInterval);
    writeConnectorExtension(node, c);
    writeTargetPort(node, "sourceDataPort", c.source);
    writeTargetPort(node, "targetDataPort", c.target);
    writeProperties(node, c.properties);
    c.extras.applyTo(node);
}

void writeServicePortConnector(XmlNode &parent, const RtsServicePortConnector &c)
{
    XmlNode &node
        = writeConnectorBase(parent, "ServicePortConnectors", "serviceport_connector_ext", c);
    node.setAttribute(Ns::Rts, n("transMethod"), c.transMethod);
    writeConnectorExtension(node, c);
    writeTargetPort(node, "sourceServicePort", c.source);
    writeTargetPort(node, "targetServicePort", c.target);
    writeProperties(node, c.properties);
    c.extras.applyTo(node);
}

void writePreceding(XmlNode &parent, const RtsPreceding &p)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("Preceding"));
    node.setAttribute(Ns::Rts, n("timeout"), p.timeout);
    node.setAttribute(Ns::Rts, n("sendingTiming"), p.sendingTiming);
    for (const RtsTargetExecutionContext &t : p.precedingComponents)
        writeTargetExecutionContext(node, "PrecedingComponents", t);
    p.extras.applyTo(node);
}

void writeCondition(XmlNode &parent, const RtsCondition &c)
{
    XmlNode &node = parent.addChild(Ns::Rts, n("targets"));
    node.setXsiType(Ns::RtsExt, n("condition_ext"));
    node.setAttribute(Ns::Rts, n("sequence"), c.sequence);
    if (c.waitTime) {
        XmlNode &wait = node.addChild(Ns::Rts, n("WaitTime"));
        wait.setAttribute(Ns::Rts, n("waitTime"), c.waitTime->waitTime);
        c.waitTime->extras.applyTo(wait);
    }
    if (c.preceding)
        writePreceding(node, *c.preceding);
    writeTargetExecutionContext(node, "TargetComponent", c.targetComponent);
    writeProperties(node, c.properties);
    c.extras.applyTo(node);
}

void writeSequence(XmlNode &parent, RtsSequenceKind kind, const RtsMessageSequence &s)
{
    XmlNode &node = parent.addChild(Ns::Rts, rtsSequenceElementName(kind));
    for (const RtsCondition &c : s.targets)
        writeCondition(node, c);
    s.extras.applyTo(node);
}

void writeRootAttributes(XmlNode &root, const RtsProfile &p)
{
    root.setAttribute(Ns::Rts, n("id"), p.id);
    root.setAttribute(Ns::Rts, n("version"), p.version);
    root.setAttribute(Ns::Rts, n("abstract"), p.abstract);
    root.setAttribute(Ns::Rts, n("creationDate"), p.creationDate);
    root.setAttribute(Ns::Rts, n("updateDate"), p.updateDate);
    root.setAttribute(Ns::RtsExt, n("comment"), p.comment);
}

void writeExtension(XmlNode &root, const RtsProfile &p)
{
    for (const QString &log : p.versionUpLogs)
        root.addChild(Ns::RtsExt, n("VersionUpLogs")).text = log;
    writeProperties(root, p.properties);
    for (const RtsSystemPath &system : p.systems) {
        XmlNode &node = root.addChild(Ns::RtsExt, n("Systems"));
        node.setAttribute(Ns::RtsExt, n("path"), system.path);
        system.extras.applyTo(node);
    }
}

} // namespace

QByteArray writeRtsXml(const RtsProfile &profile)
{
    XmlNode root(Ns::Rts, n("RtsProfile"));
    root.prefix = Ns::preferredPrefix(Ns::Rts);
    writeRootAttributes(root, profile);
    root.children.reserve(std::size_t(profile.components.size() + profile.dataPortConnectors.size()
                                      + profile.servicePortConnectors.size() + 16));
    for (const RtsComponent &c : profile.components)
        writeComponent(root, c);
    for (const RtsGroup &g : profile.groups)
        writeGroup(root, g);
    for (const RtsDataPortConnector &c : profile.dataPortConnectors)
        writeDataPortConnector(root, c);
    for (const RtsServicePortConnector &c : profile.servicePortConnectors)
        writeServicePortConnector(root, c);
    for (RtsSequenceKind kind : rtsSequenceKinds()) {
        if (const auto &sequence = profile.sequence(kind))
            writeSequence(root, kind, *sequence);
    }
    writeExtension(root, profile);
    profile.extras.applyTo(root);
    return serializeXml(root);
}

} // namespace Profile
