// SPDX-License-Identifier: MIT
// Writes rtsprofile's YAML dialect. Values keep the model's text; the scalar style is chosen so
// that YAML tools see text as text (a version "0.2" stays a string) and numbers as numbers.
#include "rtsyaml.h"
#include "rtsyamlmap_p.h"

#include <QRegularExpression>

namespace Profile {

namespace {

using namespace RtsYaml;

/// YAML 1.1 (PyYAML, used by rtsprofile) would resolve this plain scalar to a number.
bool looksNumeric(const QString &text)
{
    static const QRegularExpression number(QStringLiteral(
        R"(^[-+]?(\d[\d_]*(\.[\d_]*)?|\.\d+)([eE][-+]?\d+)?$|^0x[0-9a-fA-F_]+$|^[-+]?\.(inf|Inf|INF)$)"
        R"(|^\.(nan|NaN|NAN)$|^[-+]?[1-9][\d_]*(:[0-5]?\d)+(\.[\d_]*)?$)"));
    return number.match(text).hasMatch();
}

/// This text would not come back as the same text from a plain scalar: a number, a YAML 1.1
/// boolean or null, or nothing at all.
bool needsQuotes(const QString &text)
{
    static const QRegularExpression special(QStringLiteral(
        R"(^(y|Y|yes|Yes|YES|n|N|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF|null|Null|NULL|~)$)"));
    return text.isEmpty() || looksNumeric(text) || special.match(text).hasMatch();
}

class RtsYamlWriter
{
public:
    explicit RtsYamlWriter(YAML::Emitter &out)
        : m_out(out)
    { }

    void writeProfile(const RtsProfile &p)
    {
        m_out << YAML::BeginMap << YAML::Key << "rtsProfile" << YAML::Value << YAML::BeginMap;
        text("id", p.id);
        text("version", p.version);
        text("abstract", p.abstract);
        date("creationDate", p.creationDate);
        date("updateDate", p.updateDate);
        text(ext("comment"), p.comment);
        list("components", p.components, &RtsYamlWriter::writeComponent);
        list("groups", p.groups, &RtsYamlWriter::writeGroup);
        list("dataPortConnectors", p.dataPortConnectors, &RtsYamlWriter::writeDataPortConnector);
        list("servicePortConnectors", p.servicePortConnectors,
             &RtsYamlWriter::writeServicePortConnector);
        for (RtsSequenceKind kind : rtsSequenceKinds()) {
            if (const auto &sequence = p.sequence(kind)) {
                key(rtsSequenceYamlKey(kind));
                writeSequence(*sequence);
            }
        }
        writeStrings(ext("versionUpLogs"), p.versionUpLogs);
        properties(p.properties);
        list(ext("systems"), p.systems, &RtsYamlWriter::writeSystemPath);
        extras(p.yamlExtras);
        m_out << YAML::EndMap << YAML::EndMap;
    }

private:
    void key(const QString &name)
    {
        m_out << YAML::Key;
        // YAML allows 1024 characters in a plain `key:`; a longer one (once escaped) must be `? key`.
        if (name.size() > 128)
            m_out << YAML::LongKey;
        // The dialect quotes its namespaced keys.
        if (name.contains(QLatin1String("::")))
            m_out << YAML::DoubleQuoted;
        m_out << toStd(name) << YAML::Value;
    }
    void key(const char *name) { key(QString::fromLatin1(name)); }

    /// Text that must stay text for YAML readers.
    void text(const QString &name, const QString &value)
    {
        key(name);
        if (needsQuotes(value))
            m_out << YAML::SingleQuoted;
        m_out << toStd(value);
    }
    void text(const char *name, const QString &value) { text(QString::fromLatin1(name), value); }
    void text(const QString &name, const std::optional<QString> &value)
    {
        if (value)
            text(name, *value);
    }
    void text(const char *name, const std::optional<QString> &value)
    {
        text(QString::fromLatin1(name), value);
    }

    /// A number written plain; text that is no number is written as text so that it survives.
    void number(const char *name, const QString &value)
    {
        key(name);
        if (!looksNumeric(value))
            m_out << YAML::SingleQuoted;
        m_out << toStd(value);
    }
    void number(const char *name, const std::optional<QString> &value)
    {
        if (value)
            number(name, *value);
    }

    /// rtsprofile writes its booleans as the strings 'true'/'false' (and compares them so).
    void boolean(const QString &name, const QString &value)
    {
        key(name);
        m_out << YAML::SingleQuoted << toStd(value);
    }
    void boolean(const QString &name, const std::optional<QString> &value)
    {
        if (value)
            boolean(name, *value);
    }

    void date(const char *name, const QString &value)
    {
        static const QRegularExpression pattern(QStringLiteral(
            R"(^(\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2})(?:\.(\d+))?(Z|[+-]\d{2}:\d{2})?$)"));
        const QRegularExpressionMatch match = pattern.match(value);
        if (!match.hasMatch()) {
            text(name, value); // not rtsprofile's form, but nothing is lost
            return;
        }
        key(name);
        m_out << YAML::BeginMap;
        static const char *const parts[] = {"year", "month", "day", "hour", "minute", "second"};
        for (int i = 0; i < 6; ++i)
            m_out << YAML::Key << parts[i] << YAML::Value << match.captured(i + 1).toInt();
        // Quoted: "+10:00" would be a base-60 number to YAML 1.1, "500" a number.
        if (match.hasCaptured(7))
            m_out << YAML::Key << "fraction" << YAML::Value << YAML::SingleQuoted
                  << toStd(match.captured(7));
        if (match.hasCaptured(8))
            m_out << YAML::Key << "timeZone" << YAML::Value << YAML::SingleQuoted
                  << toStd(match.captured(8));
        m_out << YAML::EndMap;
    }

    template<typename T, typename Key>
    void list(const Key &name, const QList<T> &items, void (RtsYamlWriter::*write)(const T &))
    {
        if (items.isEmpty())
            return;
        key(name);
        m_out << YAML::BeginSeq;
        for (const T &item : items)
            (this->*write)(item);
        m_out << YAML::EndSeq;
    }

    void writeStrings(const QString &name, const QStringList &values)
    {
        if (values.isEmpty())
            return;
        key(name);
        m_out << YAML::BeginSeq;
        for (const QString &value : values) {
            if (needsQuotes(value))
                m_out << YAML::SingleQuoted;
            m_out << toStd(value);
        }
        m_out << YAML::EndSeq;
    }

    /// Unknown keys as read; an entry whose text no longer parses is dropped rather than
    /// breaking the file (it was produced by yaml-cpp, so this does not happen in practice).
    void extras(const RtsYamlExtras &extras, const QString &prefix = QString())
    {
        for (const RtsYamlExtras::Entry &e : extras.entries) {
            const bool inner = e.key.startsWith(QLatin1String("condition/"));
            if (inner != !prefix.isEmpty())
                continue;
            try {
                const YAML::Node value = YAML::Load(toStd(e.yaml));
                key(e.key.mid(prefix.size()));
                m_out << value;
            } catch (const YAML::Exception &) {
                continue;
            }
        }
    }

    void properties(const RtsProperties &items)
    {
        list(ext("properties"), items, &RtsYamlWriter::writeProperty);
    }

    void writeProperty(const RtsProperty &p)
    {
        m_out << YAML::BeginMap;
        text("name", p.name);
        text("value", p.value);
        extras(p.yamlExtras);
        m_out << YAML::EndMap;
    }

    void targetBase(const RtsTargetComponent &t)
    {
        text("componentId", t.componentId);
        text("instanceName", t.instanceName);
        properties(t.properties);
    }

    void writeTargetComponent(const RtsTargetComponent &t)
    {
        m_out << YAML::BeginMap;
        targetBase(t);
        extras(t.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeTargetPort(const RtsTargetPort &t)
    {
        m_out << YAML::BeginMap;
        targetBase(t);
        text("portName", t.portName);
        extras(t.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeTargetExecutionContext(const RtsTargetExecutionContext &t)
    {
        m_out << YAML::BeginMap;
        targetBase(t);
        text("id", t.id);
        extras(t.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writePort(const RtsPort &port)
    {
        m_out << YAML::BeginMap;
        text("name", port.name);
        text(ext("comment"), port.comment);
        boolean(ext("visible"), port.visible);
        properties(port.properties);
        extras(port.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeConfigurationData(const RtsConfigurationData &data)
    {
        m_out << YAML::BeginMap;
        text("name", data.name);
        text("data", data.data);
        extras(data.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeConfigurationSet(const RtsConfigurationSet &set)
    {
        m_out << YAML::BeginMap;
        text("id", set.id);
        list("configurationData", set.data, &RtsYamlWriter::writeConfigurationData);
        extras(set.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeExecutionContext(const RtsExecutionContext &ec)
    {
        m_out << YAML::BeginMap;
        text("id", ec.id);
        text("kind", ec.kind);
        number("rate", ec.rate);
        list("participants", ec.participants, &RtsYamlWriter::writeTargetComponent);
        properties(ec.properties);
        extras(ec.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeParticipant(const RtsParticipant &participant)
    {
        m_out << YAML::BeginMap;
        key("participant");
        writeTargetComponent(participant.participant);
        extras(participant.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeLocation(const RtsLocation &l)
    {
        m_out << YAML::BeginMap;
        number("x", l.x);
        number("y", l.y);
        number("height", l.height);
        number("width", l.width);
        text("direction", l.direction);
        extras(l.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeComponent(const RtsComponent &c)
    {
        m_out << YAML::BeginMap;
        text("id", c.id);
        text("pathUri", c.pathUri);
        text("instanceName", c.instanceName);
        text("activeConfigurationSet", c.activeConfigurationSet);
        text("compositeType", c.compositeType);
        boolean(QStringLiteral("isRequired"), c.isRequired);
        text(ext("comment"), c.comment);
        boolean(ext("visible"), c.visible);
        list("dataPorts", c.dataPorts, &RtsYamlWriter::writePort);
        list("servicePorts", c.servicePorts, &RtsYamlWriter::writePort);
        list("configurationSets", c.configurationSets, &RtsYamlWriter::writeConfigurationSet);
        list("executionContexts", c.executionContexts, &RtsYamlWriter::writeExecutionContext);
        list("participants", c.participants, &RtsYamlWriter::writeParticipant);
        if (c.layout) {
            key(ext("location"));
            writeLocation(*c.layout);
        }
        properties(c.properties);
        extras(c.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeGroup(const RtsGroup &g)
    {
        m_out << YAML::BeginMap;
        text("groupId", g.groupId);
        list("members", g.members, &RtsYamlWriter::writeTargetComponent);
        extras(g.yamlExtras);
        m_out << YAML::EndMap;
    }

    void connectorBase(const RtsPortConnector &c)
    {
        text("connectorId", c.connectorId);
        text("name", c.name);
        text(ext("comment"), c.comment);
        boolean(ext("visible"), c.visible);
    }

    void connectorEnds(const char *sourceKey, const char *targetKey, const RtsPortConnector &c)
    {
        key(sourceKey);
        writeTargetPort(c.source);
        key(targetKey);
        writeTargetPort(c.target);
        properties(c.properties);
        extras(c.yamlExtras);
    }

    void writeDataPortConnector(const RtsDataPortConnector &c)
    {
        m_out << YAML::BeginMap;
        connectorBase(c);
        text("dataType", c.dataType);
        text("interfaceType", c.interfaceType);
        text("dataflowType", c.dataflowType);
        text("subscriptionType", c.subscriptionType);
        number("pushInterval", c.pushInterval);
        connectorEnds("sourceDataPort", "targetDataPort", c);
        m_out << YAML::EndMap;
    }

    void writeServicePortConnector(const RtsServicePortConnector &c)
    {
        m_out << YAML::BeginMap;
        connectorBase(c);
        text("transMethod", c.transMethod);
        connectorEnds("sourceServicePort", "targetServicePort", c);
        m_out << YAML::EndMap;
    }

    void writePreceding(const RtsPreceding &p)
    {
        m_out << YAML::BeginMap;
        number("timeout", p.timeout);
        text("sendingTiming", p.sendingTiming);
        list("precedingComponents", p.precedingComponents,
             &RtsYamlWriter::writeTargetExecutionContext);
        extras(p.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeConditionChoice(const RtsCondition &c)
    {
        key("condition");
        m_out << YAML::BeginMap;
        if (c.waitTime) {
            key("waitTime");
            m_out << YAML::BeginMap;
            number("waitTime", c.waitTime->waitTime);
            extras(c.waitTime->yamlExtras);
            m_out << YAML::EndMap;
        }
        if (c.preceding) {
            key("preceding");
            writePreceding(*c.preceding);
        }
        extras(c.yamlExtras, QStringLiteral("condition/"));
        m_out << YAML::EndMap;
    }

    void writeCondition(const RtsCondition &c)
    {
        m_out << YAML::BeginMap;
        number("sequence", c.sequence);
        key("targetComponent");
        writeTargetExecutionContext(c.targetComponent);
        // Always present: rtsprofile looks the key up unconditionally.
        writeConditionChoice(c);
        properties(c.properties);
        extras(c.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeSequence(const RtsMessageSequence &s)
    {
        m_out << YAML::BeginMap;
        list("targets", s.targets, &RtsYamlWriter::writeCondition);
        extras(s.yamlExtras);
        m_out << YAML::EndMap;
    }

    void writeSystemPath(const RtsSystemPath &s)
    {
        m_out << YAML::BeginMap;
        text("path", s.path);
        extras(s.yamlExtras);
        m_out << YAML::EndMap;
    }

    YAML::Emitter &m_out;
};

} // namespace

QByteArray writeRtsYaml(const RtsProfile &profile)
{
    YAML::Emitter out;
    out.SetIndent(4);
    RtsYamlWriter(out).writeProfile(profile);
    QByteArray result(out.c_str(), qsizetype(out.size()));
    result.append('\n');
    return result;
}

} // namespace Profile
