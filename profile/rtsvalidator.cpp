// SPDX-License-Identifier: MIT
// All look-ups go through hashes built once, so that a system with thousands of components and
// connectors validates in linear time.
#include "rtsvalidator.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsValidator", text);
}

/// What the checks need to know about one component, found by instance name.
struct ComponentInfo
{
    const RtsComponent *component = nullptr;
    QSet<QString> ports;
    QSet<QString> contexts;
};

class RtsValidator
{
public:
    RtsValidator(const RtsProfile &profile, const QString &fileName)
        : m_profile(profile)
        , m_fileName(fileName)
    { }

    Diagnostics run()
    {
        checkSystem();
        indexComponents();
        for (const RtsComponent &c : m_profile.components)
            checkComponent(c);
        for (const RtsGroup &g : m_profile.groups) {
            for (const RtsTargetComponent &member : g.members)
                checkReference(member, tr("group %1").arg(g.groupId));
        }
        checkConnectors();
        for (RtsSequenceKind kind : rtsSequenceKinds()) {
            if (const auto &sequence = m_profile.sequence(kind))
                checkSequence(rtsSequenceElementName(kind), *sequence);
        }
        return m_diagnostics;
    }

private:
    void add(Diagnostic::Severity severity, const SourceLocation &where, const QString &object,
             const QString &message)
    {
        Diagnostic d = Diagnostic::error(m_fileName, where.line, where.column, message);
        d.severity = severity;
        d.object = object;
        m_diagnostics.append(d);
    }
    void error(const SourceLocation &where, const QString &object, const QString &message)
    {
        add(Diagnostic::Severity::Error, where, object, message);
    }
    void warning(const SourceLocation &where, const QString &object, const QString &message)
    {
        add(Diagnostic::Severity::Warning, where, object, message);
    }

    static bool isInteger(const QString &text)
    {
        bool ok = false;
        text.trimmed().toLongLong(&ok);
        return ok;
    }
    static bool isNumber(const QString &text)
    {
        bool ok = false;
        text.trimmed().toDouble(&ok);
        return ok;
    }

    void checkInteger(const SourceLocation &where, const QString &object, const char *what,
                      const std::optional<QString> &value)
    {
        if (value && !isInteger(*value))
            error(where, object,
                  tr("%1 '%2' is not a whole number").arg(QLatin1String(what), *value));
    }
    void checkNumber(const SourceLocation &where, const QString &object, const char *what,
                     const std::optional<QString> &value)
    {
        if (value && !isNumber(*value))
            error(where, object, tr("%1 '%2' is not a number").arg(QLatin1String(what), *value));
    }
    void checkBoolean(const SourceLocation &where, const QString &object, const char *what,
                      const std::optional<QString> &value)
    {
        if (value && !parseBoolean(*value))
            warning(where, object,
                    tr("%1 '%2' is not true or false").arg(QLatin1String(what), *value));
    }

    void checkSystem()
    {
        const QString object = tr("system");
        if (!m_profile.systemId()) {
            warning(m_profile.location, object,
                    tr("system id '%1' does not have the form RTSystem:vendor:name:version")
                        .arg(m_profile.id));
        }
    }

    void indexComponents()
    {
        m_components.reserve(m_profile.components.size());
        for (const RtsComponent &c : m_profile.components) {
            if (m_components.contains(c.instanceName)) {
                error(c.location, tr("component %1").arg(c.instanceName),
                      tr("instance name '%1' is used by more than one component")
                          .arg(c.instanceName));
                continue;
            }
            ComponentInfo info;
            info.component = &c;
            for (const RtsPort &p : c.dataPorts)
                info.ports.insert(p.name);
            for (const RtsPort &p : c.servicePorts)
                info.ports.insert(p.name);
            for (const RtsExecutionContext &ec : c.executionContexts)
                info.contexts.insert(ec.id);
            m_components.insert(c.instanceName, info);
        }
    }

    void checkLocation(const RtsLocation &l, const QString &object)
    {
        checkInteger(l.location, object, "x", l.x);
        checkInteger(l.location, object, "y", l.y);
        checkInteger(l.location, object, "height", l.height);
        checkInteger(l.location, object, "width", l.width);
        if (!RtsLocation::directions().contains(l.direction)) {
            warning(l.location, object,
                    tr("direction '%1' is none of UP, DOWN, LEFT, RIGHT").arg(l.direction));
        }
    }

    void checkComponent(const RtsComponent &c)
    {
        const QString object = tr("component %1").arg(c.instanceName);
        if (c.instanceName.isEmpty())
            error(c.location, object, tr("the component has no instance name"));
        if (!RtsComponentTypeId::parse(c.id)) {
            warning(c.location, object,
                    tr("component id '%1' does not have the form RTC:vendor:category:name:version")
                        .arg(c.id));
        }
        if (c.compositeType && !RtsComponent::compositeTypes().contains(*c.compositeType))
            warning(c.location, object, tr("unknown composite type '%1'").arg(*c.compositeType));
        checkBoolean(c.location, object, "isRequired", c.isRequired);
        checkBoolean(c.location, object, "visible", c.visible);
        checkActiveConfigurationSet(c, object);
        for (const RtsExecutionContext &ec : c.executionContexts)
            checkNumber(ec.location, object, "execution context rate", ec.rate);
        for (const RtsParticipant &p : c.participants)
            checkReference(p.participant, object);
        if (c.layout)
            checkLocation(*c.layout, object);
    }

    void checkActiveConfigurationSet(const RtsComponent &c, const QString &object)
    {
        if (!c.activeConfigurationSet || c.configurationSets.isEmpty())
            return;
        for (const RtsConfigurationSet &set : c.configurationSets) {
            if (set.id == *c.activeConfigurationSet)
                return;
        }
        warning(c.location, object,
                tr("the active configuration set '%1' is not one of the "
                   "component's sets")
                    .arg(*c.activeConfigurationSet));
    }

    /// rtsprofile's samples use '.' where ':' belongs (`RTC:v.c.n:1.0`); that is the same id.
    static bool sameComponentId(const QString &a, const QString &b)
    {
        if (a == b)
            return true;
        QString left = a;
        QString right = b;
        return left.replace(QLatin1Char('.'), QLatin1Char(':'))
            == right.replace(QLatin1Char('.'), QLatin1Char(':'));
    }

    /// The component a reference names, or null after reporting that it names none.
    const ComponentInfo *checkReference(const RtsTargetComponent &t, const QString &object)
    {
        const auto found = m_components.constFind(t.instanceName);
        if (found == m_components.cend()) {
            error(t.location, object,
                  tr("'%1' names no component of the system").arg(t.instanceName));
            return nullptr;
        }
        if (!sameComponentId(t.componentId, found->component->id)) {
            warning(t.location, object,
                    tr("component id '%1' of '%2' differs from the component's id '%3'")
                        .arg(t.componentId, t.instanceName, found->component->id));
        }
        return &*found;
    }

    void checkConnectorEnd(const RtsTargetPort &end, const QString &object)
    {
        const ComponentInfo *info = checkReference(end, object);
        if (info && !info->ports.isEmpty() && !info->ports.contains(end.portName)) {
            warning(end.location, object,
                    tr("component '%1' has no port '%2'").arg(end.instanceName, end.portName));
        }
    }

    /// The RT System Editor's offline list offers `overerite` for the buffer-full policies.
    void checkConnectorProperties(const RtsPortConnector &c, const QString &object)
    {
        for (const RtsProperty &p : c.properties) {
            if (p.name.endsWith(QLatin1String("full_policy"))
                && p.value == QLatin1String("overerite")) {
                warning(p.location, object,
                        tr("'%1': 'overerite' (RT System Editor's typo) means 'overwrite'")
                            .arg(p.name));
            }
        }
    }

    void checkConnectorCommon(const RtsPortConnector &c, QSet<QString> &ids)
    {
        const QString object = tr("connector %1").arg(c.name);
        if (ids.contains(c.connectorId))
            error(c.location, object,
                  tr("connector id '%1' is used more than once").arg(c.connectorId));
        ids.insert(c.connectorId);
        checkConnectorEnd(c.source, object);
        checkConnectorEnd(c.target, object);
        checkBoolean(c.location, object, "visible", c.visible);
        checkConnectorProperties(c, object);
    }

    void checkConnectors()
    {
        QSet<QString> ids;
        ids.reserve(m_profile.dataPortConnectors.size() + m_profile.servicePortConnectors.size());
        for (const RtsDataPortConnector &c : m_profile.dataPortConnectors) {
            checkConnectorCommon(c, ids);
            checkNumber(c.location, tr("connector %1").arg(c.name), "push interval",
                        c.pushInterval);
        }
        for (const RtsServicePortConnector &c : m_profile.servicePortConnectors)
            checkConnectorCommon(c, ids);
    }

    void checkExecutionContextReference(const RtsTargetExecutionContext &t, const QString &object)
    {
        const ComponentInfo *info = checkReference(t, object);
        if (info && !info->contexts.isEmpty() && !info->contexts.contains(t.id)) {
            warning(t.location, object,
                    tr("component '%1' has no execution context '%2'").arg(t.instanceName, t.id));
        }
    }

    void checkPreceding(const RtsPreceding &p, const QString &object)
    {
        checkInteger(p.location, object, "timeout", p.timeout);
        if (p.sendingTiming && !RtsPreceding::sendingTimings().contains(*p.sendingTiming))
            warning(p.location, object, tr("unknown sending timing '%1'").arg(*p.sendingTiming));
        for (const RtsTargetExecutionContext &t : p.precedingComponents)
            checkExecutionContextReference(t, object);
    }

    void checkSequence(const QString &name, const RtsMessageSequence &sequence)
    {
        for (const RtsCondition &c : sequence.targets) {
            const QString object = tr("%1 target %2").arg(name, c.targetComponent.instanceName);
            checkInteger(c.location, object, "sequence", c.sequence);
            checkExecutionContextReference(c.targetComponent, object);
            if (c.waitTime)
                checkInteger(c.waitTime->location, object, "wait time", c.waitTime->waitTime);
            if (c.preceding)
                checkPreceding(*c.preceding, object);
            if (c.waitTime && c.preceding)
                warning(c.location, object,
                        tr("a target has both a wait time and preceding components"));
        }
    }

    const RtsProfile &m_profile;
    QString m_fileName;
    QHash<QString, ComponentInfo> m_components;
    Diagnostics m_diagnostics;
};

} // namespace

Diagnostics validateRtsProfile(const RtsProfile &profile, const QString &fileName)
{
    return RtsValidator(profile, fileName).run();
}

} // namespace Profile
