// SPDX-License-Identifier: MIT
// Reads rtsprofile's YAML dialect into RtsProfile. Every yaml-cpp call that can throw runs inside
// readRtsYaml's try block; structural problems (a list where a value belongs …) are reported at the
// node's mark and the reader carries on, so one file shows all its problems at once.
#include "rtsyaml.h"
#include "rtsyamlmap_p.h"

#include <QCoreApplication>

namespace Profile {

namespace {

using namespace RtsYaml;

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsYaml", text);
}

constexpr qint64 MaxYamlBytes = 512LL * 1024 * 1024;

QString normalizedBoolean(const QString &text)
{
    const auto value = parseBoolean(text);
    return value ? booleanText(*value) : text;
}

/// Maps the YAML nodes of a profile onto the model; one function per part.
class RtsYamlReader
{
public:
    explicit RtsYamlReader(const Context &context)
        : m_context(context)
    { }

    RtsProfile readProfile(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsProfile p;
        p.id = m.required("id");
        p.version = m.required("version");
        p.abstract = m.scalar("abstract");
        p.creationDate = readDate(m, "creationDate");
        p.updateDate = readDate(m, "updateDate");
        p.comment = m.scalar(ext("comment"));
        p.components = readList<RtsComponent>(m, "components", &RtsYamlReader::readComponent);
        p.groups = readList<RtsGroup>(m, "groups", &RtsYamlReader::readGroup);
        p.dataPortConnectors = readList<RtsDataPortConnector>(
            m, "dataPortConnectors", &RtsYamlReader::readDataPortConnector);
        p.servicePortConnectors = readList<RtsServicePortConnector>(
            m, "servicePortConnectors", &RtsYamlReader::readServicePortConnector);
        for (RtsSequenceKind kind : rtsSequenceKinds()) {
            if (const auto sequence = m.map(rtsSequenceYamlKey(kind)))
                p.sequence(kind) = readSequence(*sequence);
        }
        p.versionUpLogs = readStrings(m, ext("versionUpLogs"));
        p.properties = readProperties(m);
        p.systems = readList<RtsSystemPath>(m, ext("systems"), &RtsYamlReader::readSystemPath);
        finish(p, m);
        return p;
    }

private:
    template<typename T> void finish(T &item, const Map &m)
    {
        item.yamlExtras = m.extras();
        item.location = m.location();
    }

    /// Each list entry must be a mapping; others are reported and skipped.
    template<typename T, typename Key>
    QList<T> readList(Map &m, const Key &key, T (RtsYamlReader::*read)(const YAML::Node &))
    {
        QList<T> result;
        const auto list = m.sequence(key);
        if (!list)
            return result;
        result.reserve(qsizetype(list->size()));
        for (const YAML::Node &entry : *list) {
            if (entry.IsMap())
                result.append((this->*read)(entry));
            else
                m_context.error(entry.Mark(), tr("each entry of '%1' must be a mapping").arg(key));
        }
        return result;
    }

    QStringList readStrings(Map &m, const QString &key)
    {
        QStringList result;
        const auto list = m.sequence(key);
        if (!list)
            return result;
        for (const YAML::Node &entry : *list) {
            if (entry.IsScalar())
                result.append(fromStd(entry.Scalar()));
            else
                m_context.error(entry.Mark(), tr("each entry of '%1' must be text").arg(key));
        }
        return result;
    }

    /// rtsprofile's {year, month, day, hour, minute, second} (+ this project's fraction and
    /// timeZone, which keep OpenRTP's milliseconds and offsets); plain text is taken as it is.
    QString readDate(Map &m, const char *key)
    {
        const QString name = QLatin1String(key);
        const auto date = m.value(name);
        if (!date || date->IsNull()) {
            m_context.error(m.node().Mark(),
                            tr("the mapping lacks the required key '%1'").arg(name));
            return {};
        }
        if (date->IsMap())
            return readDateMap(*date, name);
        if (date->IsScalar())
            return fromStd(date->Scalar());
        m_context.error(date->Mark(), tr("'%1' must be a date").arg(name));
        return {};
    }

    int readDatePart(Map &m, const char *part, const QString &name)
    {
        const auto value = m.value(QLatin1String(part));
        bool ok = false;
        const int number = value && value->IsScalar() ? fromStd(value->Scalar()).toInt(&ok) : 0;
        if (!value)
            m_context.error(m.node().Mark(), tr("'%1' lacks '%2'").arg(name, QLatin1String(part)));
        else if (!ok)
            m_context.error(value->Mark(),
                            tr("'%1.%2' must be a whole number").arg(name, QLatin1String(part)));
        return number;
    }

    QString readDateMap(const YAML::Node &node, const QString &name)
    {
        Map m(node, m_context);
        const int year = readDatePart(m, "year", name);
        const int month = readDatePart(m, "month", name);
        const int day = readDatePart(m, "day", name);
        const int hour = readDatePart(m, "hour", name);
        const int minute = readDatePart(m, "minute", name);
        const int second = readDatePart(m, "second", name);
        QString text = QStringLiteral("%1-%2-%3T%4:%5:%6")
                           .arg(year, 4, 10, QLatin1Char('0'))
                           .arg(month, 2, 10, QLatin1Char('0'))
                           .arg(day, 2, 10, QLatin1Char('0'))
                           .arg(hour, 2, 10, QLatin1Char('0'))
                           .arg(minute, 2, 10, QLatin1Char('0'))
                           .arg(second, 2, 10, QLatin1Char('0'));
        if (const auto fraction = m.scalar("fraction"))
            text += QLatin1Char('.') + *fraction;
        if (const auto zone = m.scalar("timeZone"))
            text += *zone;
        return text;
    }

    RtsProperties readProperties(Map &m)
    {
        return readList<RtsProperty>(m, ext("properties"), &RtsYamlReader::readProperty);
    }

    RtsProperty readProperty(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsProperty p;
        p.name = m.required("name");
        p.value = m.scalar("value");
        finish(p, m);
        return p;
    }

    void readTargetBase(Map &m, RtsTargetComponent &t)
    {
        t.componentId = m.required("componentId");
        t.instanceName = m.required("instanceName");
        t.properties = readProperties(m);
    }

    RtsTargetComponent readTargetComponent(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsTargetComponent t;
        readTargetBase(m, t);
        finish(t, m);
        return t;
    }

    RtsTargetPort readTargetPort(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsTargetPort t;
        readTargetBase(m, t);
        t.portName = m.required("portName");
        finish(t, m);
        return t;
    }

    RtsTargetExecutionContext readTargetExecutionContext(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsTargetExecutionContext t;
        readTargetBase(m, t);
        t.id = m.required("id");
        finish(t, m);
        return t;
    }

    RtsPort readPort(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsPort port;
        port.name = m.required("name");
        port.comment = m.scalar(ext("comment"));
        if (const auto visible = m.scalar(ext("visible")))
            port.visible = normalizedBoolean(*visible);
        port.properties = readProperties(m);
        finish(port, m);
        return port;
    }

    RtsConfigurationData readConfigurationData(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsConfigurationData data;
        data.name = m.required("name");
        data.data = m.scalar("data");
        finish(data, m);
        return data;
    }

    RtsConfigurationSet readConfigurationSet(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsConfigurationSet set;
        set.id = m.required("id");
        set.data = readList<RtsConfigurationData>(m, "configurationData",
                                                  &RtsYamlReader::readConfigurationData);
        finish(set, m);
        return set;
    }

    RtsExecutionContext readExecutionContext(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsExecutionContext ec;
        ec.id = m.required("id");
        ec.kind = m.required("kind");
        ec.rate = m.scalar("rate");
        ec.participants
            = readList<RtsTargetComponent>(m, "participants", &RtsYamlReader::readTargetComponent);
        ec.properties = readProperties(m);
        finish(ec, m);
        return ec;
    }

    RtsParticipant readParticipant(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsParticipant participant;
        if (const auto target = m.map("participant"))
            participant.participant = readTargetComponent(*target);
        else
            m_context.error(node.Mark(), tr("a participant lacks its 'participant' mapping"));
        finish(participant, m);
        return participant;
    }

    RtsLocation readLocation(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsLocation l;
        l.x = m.required("x");
        l.y = m.required("y");
        l.height = m.required("height");
        l.width = m.required("width");
        l.direction = m.required("direction");
        if (RtsLocation::directions().contains(l.direction.trimmed().toUpper()))
            l.direction = l.direction.trimmed().toUpper();
        finish(l, m);
        return l;
    }

    void readComponentAttributes(Map &m, RtsComponent &c)
    {
        c.id = m.required("id");
        c.pathUri = m.required("pathUri");
        c.instanceName = m.required("instanceName");
        c.activeConfigurationSet = m.scalar("activeConfigurationSet");
        c.compositeType = m.scalar("compositeType");
        c.isRequired = normalizedBoolean(m.required("isRequired"));
        c.comment = m.scalar(ext("comment"));
        if (const auto visible = m.scalar(ext("visible")))
            c.visible = normalizedBoolean(*visible);
    }

    RtsComponent readComponent(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsComponent c;
        readComponentAttributes(m, c);
        c.dataPorts = readList<RtsPort>(m, "dataPorts", &RtsYamlReader::readPort);
        c.servicePorts = readList<RtsPort>(m, "servicePorts", &RtsYamlReader::readPort);
        c.configurationSets = readList<RtsConfigurationSet>(m, "configurationSets",
                                                            &RtsYamlReader::readConfigurationSet);
        c.executionContexts = readList<RtsExecutionContext>(m, "executionContexts",
                                                            &RtsYamlReader::readExecutionContext);
        c.participants
            = readList<RtsParticipant>(m, "participants", &RtsYamlReader::readParticipant);
        if (const auto location = m.map(ext("location")))
            c.layout = readLocation(*location);
        c.properties = readProperties(m);
        finish(c, m);
        return c;
    }

    RtsGroup readGroup(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsGroup g;
        // Accept rtsprofile's XML spelling here too, in case a converted file carries it.
        if (const auto legacy = m.scalar("groupID"))
            g.groupId = *legacy;
        else
            g.groupId = m.required("groupId");
        g.members = readList<RtsTargetComponent>(m, "members", &RtsYamlReader::readTargetComponent);
        finish(g, m);
        return g;
    }

    void readConnectorBase(Map &m, RtsPortConnector &c, const char *sourceKey,
                           const char *targetKey)
    {
        c.connectorId = m.required("connectorId");
        c.name = m.required("name");
        c.comment = m.scalar(ext("comment"));
        if (const auto visible = m.scalar(ext("visible")))
            c.visible = normalizedBoolean(*visible);
        if (const auto source = m.map(sourceKey))
            c.source = readTargetPort(*source);
        else
            m_context.error(m.node().Mark(),
                            tr("the connector lacks '%1'").arg(QLatin1String(sourceKey)));
        if (const auto target = m.map(targetKey))
            c.target = readTargetPort(*target);
        else
            m_context.error(m.node().Mark(),
                            tr("the connector lacks '%1'").arg(QLatin1String(targetKey)));
        c.properties = readProperties(m);
    }

    RtsDataPortConnector readDataPortConnector(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsDataPortConnector c;
        c.dataType = m.required("dataType");
        c.interfaceType = m.required("interfaceType");
        c.dataflowType = m.required("dataflowType");
        c.subscriptionType = m.scalar("subscriptionType");
        c.pushInterval = m.scalar("pushInterval");
        readConnectorBase(m, c, "sourceDataPort", "targetDataPort");
        finish(c, m);
        return c;
    }

    RtsServicePortConnector readServicePortConnector(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsServicePortConnector c;
        c.transMethod = m.scalar("transMethod");
        readConnectorBase(m, c, "sourceServicePort", "targetServicePort");
        finish(c, m);
        return c;
    }

    RtsWaitTime readWaitTime(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsWaitTime w;
        w.waitTime = m.scalar("waitTime");
        finish(w, m);
        return w;
    }

    RtsPreceding readPreceding(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsPreceding p;
        p.timeout = m.scalar("timeout");
        p.sendingTiming = m.scalar("sendingTiming");
        p.precedingComponents = readList<RtsTargetExecutionContext>(
            m, "precedingComponents", &RtsYamlReader::readTargetExecutionContext);
        finish(p, m);
        return p;
    }

    /// `condition: {waitTime: {…}}` or `{preceding: {…}}`; unknown keys of this inner mapping
    /// are kept on the condition with the key prefix `condition/`.
    void readConditionChoice(const YAML::Node &node, RtsCondition &c)
    {
        Map m(node, m_context);
        if (const auto wait = m.map("waitTime"))
            c.waitTime = readWaitTime(*wait);
        if (const auto preceding = m.map("preceding"))
            c.preceding = readPreceding(*preceding);
        m.addExtrasTo(c.yamlExtras, QStringLiteral("condition/"));
    }

    RtsCondition readCondition(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsCondition c;
        c.sequence = m.required("sequence");
        if (const auto target = m.map("targetComponent"))
            c.targetComponent = readTargetExecutionContext(*target);
        else
            m_context.error(node.Mark(), tr("a message-sequence target lacks 'targetComponent'"));
        if (const auto choice = m.map("condition"))
            readConditionChoice(*choice, c);
        c.properties = readProperties(m);
        m.addExtrasTo(c.yamlExtras);
        c.location = m.location();
        return c;
    }

    RtsMessageSequence readSequence(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsMessageSequence s;
        s.targets = readList<RtsCondition>(m, "targets", &RtsYamlReader::readCondition);
        finish(s, m);
        return s;
    }

    RtsSystemPath readSystemPath(const YAML::Node &node)
    {
        Map m(node, m_context);
        RtsSystemPath s;
        s.path = m.required("path");
        finish(s, m);
        return s;
    }

    const Context &m_context;
};

std::optional<RtsProfile> readDocument(const YAML::Node &document, const Context &context)
{
    if (!document.IsMap() || !document["rtsProfile"]) {
        context.error(document.Mark(),
                      tr("not an RTS Profile: expected a top-level 'rtsProfile:' mapping"));
        return std::nullopt;
    }
    for (auto it = document.begin(); it != document.end(); ++it) {
        if (it->first.Scalar() != "rtsProfile")
            context.warn(it->first.Mark(),
                         tr("the top-level key '%1' was ignored").arg(fromStd(it->first.Scalar())));
    }
    const YAML::Node profile = document["rtsProfile"];
    if (!profile.IsMap()) {
        context.error(profile.Mark(), tr("'rtsProfile' must be a mapping"));
        return std::nullopt;
    }
    return RtsYamlReader(context).readProfile(profile);
}

} // namespace

std::optional<RtsProfile> readRtsYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics)
{
    const Context context(fileName, diagnostics);
    if (data.size() > MaxYamlBytes) {
        context.error(YAML::Mark::null_mark(),
                      tr("file is larger than %1 bytes").arg(MaxYamlBytes));
        return std::nullopt;
    }
    if (!checkUtf8(data, context))
        return std::nullopt;
    try {
        const YAML::Node document = YAML::Load(data.toStdString());
        return readDocument(document, context);
    } catch (const YAML::Exception &e) {
        context.error(e.mark, fromStd(e.msg));
    } catch (const std::exception &e) {
        context.error(YAML::Mark::null_mark(),
                      tr("cannot read YAML: %1").arg(QString::fromLocal8Bit(e.what())));
    }
    return std::nullopt;
}

} // namespace Profile
