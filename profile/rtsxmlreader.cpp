// SPDX-License-Identifier: MIT
// Maps an XmlNode tree onto RtsProfile. Legacy spellings of the reference tools are accepted here
// and never written back (the writer produces the schema form).
#include "namespaces.h"
#include "rtsxml.h"
#include "xmlextras.h"

#include <QCoreApplication>

#include <algorithm>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsXml", text);
}

/// Longer attribute values are refused: no real system needs them and a GUI would choke on them.
constexpr qsizetype MaxAttributeLength = 256 * 1024;

QString rtsName(const char *name)
{
    return QString::fromLatin1(name);
}

/// xs:boolean in the form the writer uses; text that is not a boolean is kept for the validator.
QString normalizedBoolean(const QString &text)
{
    const auto value = parseBoolean(text);
    return value ? booleanText(*value) : text;
}

std::optional<QString> normalizedBoolean(const std::optional<QString> &text)
{
    return text ? std::optional<QString>(normalizedBoolean(*text)) : std::nullopt;
}

class RtsXmlReader
{
public:
    RtsXmlReader(const QString &fileName, Diagnostics *diagnostics)
        : m_fileName(fileName)
        , m_diagnostics(diagnostics)
    { }

    std::optional<RtsProfile> read(const XmlNode &root)
    {
        if (!checkRoot(root) || !checkSizes(root))
            return std::nullopt;
        return readProfile(root);
    }

private:
    NodeReader reader(const XmlNode &node) { return NodeReader(node, m_fileName, m_diagnostics); }

    void error(const SourceLocation &where, const QString &message)
    {
        if (m_diagnostics)
            m_diagnostics->append(Diagnostic::error(m_fileName, where.line, where.column, message));
    }

    bool checkRoot(const XmlNode &root)
    {
        if (root.is(Ns::Rts, rtsName("RtsProfile")))
            return true;
        if (root.name == QLatin1String("RtsProfile")) {
            error(root.location,
                  tr("the root element <RtsProfile> is in namespace '%1', expected '%2'")
                      .arg(root.namespaceUri, Ns::Rts));
        } else {
            const QString shown
                = root.prefix.isEmpty() ? root.name : root.prefix + QLatin1Char(':') + root.name;
            error(root.location,
                  tr("not an RTS Profile: the root element is <%1>, expected <rts:RtsProfile>")
                      .arg(shown));
        }
        return false;
    }

    bool checkSizes(const XmlNode &node)
    {
        for (const XmlAttribute &a : node.attributes) {
            if (a.value.size() > MaxAttributeLength) {
                error(node.location,
                      tr("the value of attribute '%1' on <%2> is %3 characters long "
                         "(at most %4 are accepted)")
                          .arg(a.name, node.name)
                          .arg(a.value.size())
                          .arg(MaxAttributeLength));
                return false;
            }
        }
        for (const XmlNode &child : node.children) {
            if (!checkSizes(child))
                return false;
        }
        return true;
    }

    template<typename T, typename Read>
    QList<T> readAll(NodeReader &r, const QString &ns, const char *name, Read read)
    {
        QList<T> result;
        const auto nodes = r.children(ns, rtsName(name));
        result.reserve(qsizetype(nodes.size()));
        for (const XmlNode *node : nodes)
            result.append((this->*read)(*node));
        return result;
    }

    template<typename T> void finish(T &item, const NodeReader &r)
    {
        item.extras = r.extras();
        item.location = r.location();
        // XmlExtras has no place for character data; say so rather than drop it silently.
        if (!r.node().text.trimmed().isEmpty())
            r.warn(tr("text inside <%1> is not part of an RTS Profile and is not kept")
                       .arg(r.node().name));
    }

    RtsProperty readProperty(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsProperty p;
        p.name = r.required(Ns::RtsExt, rtsName("name"));
        p.value = r.attribute(Ns::RtsExt, rtsName("value"));
        finish(p, r);
        return p;
    }

    RtsProperties readProperties(NodeReader &r)
    {
        return readAll<RtsProperty>(r, Ns::RtsExt, "Properties", &RtsXmlReader::readProperty);
    }

    void readTargetBase(NodeReader &r, RtsTargetComponent &t)
    {
        t.componentId = r.required(Ns::Rts, rtsName("componentId"));
        t.instanceName = r.required(Ns::Rts, rtsName("instanceName"));
    }

    RtsTargetComponent readTargetComponent(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsTargetComponent t;
        readTargetBase(r, t);
        t.properties = readProperties(r);
        finish(t, r);
        return t;
    }

    RtsTargetPort readTargetPort(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsTargetPort t;
        readTargetBase(r, t);
        t.portName = r.required(Ns::Rts, rtsName("portName"));
        t.properties = readProperties(r);
        finish(t, r);
        return t;
    }

    RtsTargetExecutionContext readTargetExecutionContext(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsTargetExecutionContext t;
        readTargetBase(r, t);
        t.id = r.required(Ns::Rts, rtsName("id"));
        t.properties = readProperties(r);
        finish(t, r);
        return t;
    }

    RtsPort readPort(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsPort port;
        port.name = r.required(Ns::Rts, rtsName("name"));
        port.comment = r.attribute(Ns::RtsExt, rtsName("comment"));
        port.visible = normalizedBoolean(r.attribute(Ns::RtsExt, rtsName("visible")));
        port.properties = readProperties(r);
        finish(port, r);
        return port;
    }

    RtsConfigurationData readConfigurationData(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsConfigurationData data;
        data.name = r.required(Ns::Rts, rtsName("name"));
        data.data = r.attribute(Ns::Rts, rtsName("data"));
        finish(data, r);
        return data;
    }

    RtsConfigurationSet readConfigurationSet(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsConfigurationSet set;
        set.id = r.required(Ns::Rts, rtsName("id"));
        set.data = readAll<RtsConfigurationData>(r, Ns::Rts, "ConfigurationData",
                                                 &RtsXmlReader::readConfigurationData);
        finish(set, r);
        return set;
    }

    RtsExecutionContext readExecutionContext(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsExecutionContext ec;
        ec.id = r.required(Ns::Rts, rtsName("id"));
        ec.kind = r.required(Ns::Rts, rtsName("kind"));
        ec.rate = r.attribute(Ns::Rts, rtsName("rate"));
        ec.participants = readAll<RtsTargetComponent>(r, Ns::Rts, "Participants",
                                                      &RtsXmlReader::readTargetComponent);
        ec.properties = readProperties(r);
        finish(ec, r);
        return ec;
    }

    RtsParticipant readParticipant(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsParticipant participant;
        if (const XmlNode *target = r.child(Ns::Rts, rtsName("Participant")))
            participant.participant = readTargetComponent(*target);
        else
            r.error(tr("<Participants> lacks its <Participant> element"));
        finish(participant, r);
        return participant;
    }

    RtsLocation readLocation(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsLocation l;
        l.x = r.required(Ns::RtsExt, rtsName("x"));
        l.y = r.required(Ns::RtsExt, rtsName("y"));
        l.height = r.required(Ns::RtsExt, rtsName("height"));
        l.width = r.required(Ns::RtsExt, rtsName("width"));
        l.direction = r.required(Ns::RtsExt, rtsName("direction"));
        // rtsprofile writes the direction in lower case; the schema's values are upper case.
        if (RtsLocation::directions().contains(l.direction.trimmed().toUpper()))
            l.direction = l.direction.trimmed().toUpper();
        finish(l, r);
        return l;
    }

    RtsComponent readComponent(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsComponent c;
        c.id = r.required(Ns::Rts, rtsName("id"));
        c.pathUri = r.required(Ns::Rts, rtsName("pathUri"));
        c.instanceName = r.required(Ns::Rts, rtsName("instanceName"));
        c.activeConfigurationSet = r.attribute(Ns::Rts, rtsName("activeConfigurationSet"));
        c.compositeType = r.attribute(Ns::Rts, rtsName("compositeType"));
        c.isRequired = normalizedBoolean(r.required(Ns::Rts, rtsName("isRequired")));
        c.comment = r.attribute(Ns::RtsExt, rtsName("comment"));
        c.visible = normalizedBoolean(r.attribute(Ns::RtsExt, rtsName("visible")));
        c.dataPorts = readAll<RtsPort>(r, Ns::Rts, "DataPorts", &RtsXmlReader::readPort);
        c.servicePorts = readAll<RtsPort>(r, Ns::Rts, "ServicePorts", &RtsXmlReader::readPort);
        c.configurationSets = readAll<RtsConfigurationSet>(r, Ns::Rts, "ConfigurationSets",
                                                           &RtsXmlReader::readConfigurationSet);
        c.executionContexts = readAll<RtsExecutionContext>(r, Ns::Rts, "ExecutionContexts",
                                                           &RtsXmlReader::readExecutionContext);
        c.participants
            = readAll<RtsParticipant>(r, Ns::Rts, "Participants", &RtsXmlReader::readParticipant);
        if (const XmlNode *location = r.child(Ns::RtsExt, rtsName("Location")))
            c.layout = readLocation(*location);
        c.properties = readProperties(r);
        finish(c, r);
        return c;
    }

    RtsGroup readGroup(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsGroup g;
        // rtsprofile writes groupID.
        g.groupId = r.required(Ns::Rts, rtsName("groupId"), {rtsName("groupID")});
        g.members = readAll<RtsTargetComponent>(r, Ns::Rts, "Members",
                                                &RtsXmlReader::readTargetComponent);
        finish(g, r);
        return g;
    }

    void readConnectorBase(NodeReader &r, RtsPortConnector &c, const char *sourceName,
                           const char *targetName)
    {
        c.connectorId = r.required(Ns::Rts, rtsName("connectorId"));
        c.name = r.required(Ns::Rts, rtsName("name"));
        c.comment = r.attribute(Ns::RtsExt, rtsName("comment"));
        c.visible = normalizedBoolean(r.attribute(Ns::RtsExt, rtsName("visible")));
        if (const XmlNode *source = r.child(Ns::Rts, rtsName(sourceName)))
            c.source = readTargetPort(*source);
        else
            r.error(tr("<%1> lacks its <%2> element").arg(r.node().name, rtsName(sourceName)));
        if (const XmlNode *target = r.child(Ns::Rts, rtsName(targetName)))
            c.target = readTargetPort(*target);
        else
            r.error(tr("<%1> lacks its <%2> element").arg(r.node().name, rtsName(targetName)));
        c.properties = readProperties(r);
    }

    RtsDataPortConnector readDataPortConnector(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsDataPortConnector c;
        c.dataType = r.required(Ns::Rts, rtsName("dataType"));
        c.interfaceType = r.required(Ns::Rts, rtsName("interfaceType"));
        c.dataflowType = r.required(Ns::Rts, rtsName("dataflowType"));
        c.subscriptionType = r.attribute(Ns::Rts, rtsName("subscriptionType"));
        c.pushInterval = r.attribute(Ns::Rts, rtsName("pushInterval"));
        readConnectorBase(r, c, "sourceDataPort", "targetDataPort");
        finish(c, r);
        return c;
    }

    RtsServicePortConnector readServicePortConnector(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsServicePortConnector c;
        c.transMethod = r.attribute(Ns::Rts, rtsName("transMethod"));
        readConnectorBase(r, c, "sourceServicePort", "targetServicePort");
        finish(c, r);
        return c;
    }

    RtsWaitTime readWaitTime(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsWaitTime w;
        w.waitTime = r.attribute(Ns::Rts, rtsName("waitTime"));
        finish(w, r);
        return w;
    }

    RtsPreceding readPreceding(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsPreceding p;
        p.timeout = r.attribute(Ns::Rts, rtsName("timeout"));
        p.sendingTiming = r.attribute(Ns::Rts, rtsName("sendingTiming"));
        p.precedingComponents = readAll<RtsTargetExecutionContext>(
            r, Ns::Rts, "PrecedingComponents", &RtsXmlReader::readTargetExecutionContext);
        finish(p, r);
        return p;
    }

    RtsCondition readCondition(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsCondition c;
        c.sequence = r.required(Ns::Rts, rtsName("sequence"));
        if (const XmlNode *target = r.child(Ns::Rts, rtsName("TargetComponent")))
            c.targetComponent = readTargetExecutionContext(*target);
        else
            r.error(tr("<targets> lacks its <TargetComponent> element"));
        if (const XmlNode *wait = r.child(Ns::Rts, rtsName("WaitTime")))
            c.waitTime = readWaitTime(*wait);
        if (const XmlNode *preceding = r.child(Ns::Rts, rtsName("Preceding")))
            c.preceding = readPreceding(*preceding);
        c.properties = readProperties(r);
        finish(c, r);
        return c;
    }

    RtsMessageSequence readSequence(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsMessageSequence s;
        s.targets = readAll<RtsCondition>(r, Ns::Rts, "targets", &RtsXmlReader::readCondition);
        finish(s, r);
        return s;
    }

    RtsSystemPath readSystemPath(const XmlNode &node)
    {
        NodeReader r = reader(node);
        RtsSystemPath s;
        s.path = r.required(Ns::RtsExt, rtsName("path"));
        finish(s, r);
        return s;
    }

    void readRootAttributes(NodeReader &r, RtsProfile &p)
    {
        p.id = r.required(Ns::Rts, rtsName("id"));
        p.version = r.required(Ns::Rts, rtsName("version"));
        p.abstract = r.attribute(Ns::Rts, rtsName("abstract"));
        p.creationDate = r.required(Ns::Rts, rtsName("creationDate"));
        p.updateDate = r.required(Ns::Rts, rtsName("updateDate"));
        p.comment = r.attribute(Ns::RtsExt, rtsName("comment"));
    }

    void readSequences(NodeReader &r, RtsProfile &p)
    {
        for (RtsSequenceKind kind : rtsSequenceKinds()) {
            // A second block of the same kind is left in the extras rather than merged.
            if (const XmlNode *node = r.child(Ns::Rts, rtsSequenceElementName(kind)))
                p.sequence(kind) = readSequence(*node);
        }
    }

    void readVersionUpLogs(NodeReader &r, RtsProfile &p)
    {
        // rtsprofile writes the singular VersionUpLog; both kinds are kept in document order.
        std::vector<const XmlNode *> logs = r.children(Ns::RtsExt, rtsName("VersionUpLogs"));
        const auto legacy = r.children(Ns::RtsExt, rtsName("VersionUpLog"));
        logs.insert(logs.end(), legacy.begin(), legacy.end());
        // The nodes live in one vector of siblings, so address order is document order.
        std::sort(logs.begin(), logs.end());
        for (const XmlNode *log : logs)
            p.versionUpLogs.append(log->text);
    }

    RtsProfile readProfile(const XmlNode &root)
    {
        NodeReader r = reader(root);
        RtsProfile p;
        readRootAttributes(r, p);
        p.components
            = readAll<RtsComponent>(r, Ns::Rts, "Components", &RtsXmlReader::readComponent);
        p.groups = readAll<RtsGroup>(r, Ns::Rts, "Groups", &RtsXmlReader::readGroup);
        p.dataPortConnectors = readAll<RtsDataPortConnector>(r, Ns::Rts, "DataPortConnectors",
                                                             &RtsXmlReader::readDataPortConnector);
        p.servicePortConnectors = readAll<RtsServicePortConnector>(
            r, Ns::Rts, "ServicePortConnectors", &RtsXmlReader::readServicePortConnector);
        readSequences(r, p);
        readVersionUpLogs(r, p);
        p.properties = readProperties(r);
        p.systems = readAll<RtsSystemPath>(r, Ns::RtsExt, "Systems", &RtsXmlReader::readSystemPath);
        finish(p, r);
        return p;
    }

    QString m_fileName;
    Diagnostics *m_diagnostics;
};

} // namespace

std::optional<RtsProfile> readRtsXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics)
{
    const std::optional<XmlNode> root = parseXml(data, fileName, diagnostics);
    if (!root)
        return std::nullopt;
    return RtsXmlReader(fileName, diagnostics).read(*root);
}

} // namespace Profile
