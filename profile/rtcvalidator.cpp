// SPDX-License-Identifier: MIT
#include "rtcvalidator.h"

#include "constraintsyntax.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcValidator", text);
}

/// Collects findings with the file name and the location of the element they are about.
class Findings
{
public:
    explicit Findings(const QString &fileName)
        : m_fileName(fileName)
    { }

    void add(Diagnostic::Severity severity, const SourceLocation &at, const QString &object,
             const QString &message)
    {
        Diagnostic d;
        d.severity = severity;
        d.file = m_fileName;
        d.line = at.line;
        d.column = at.column;
        d.object = object;
        d.message = message;
        m_result.append(d);
    }
    void error(const SourceLocation &at, const QString &object, const QString &message)
    {
        add(Diagnostic::Severity::Error, at, object, message);
    }
    void warning(const SourceLocation &at, const QString &object, const QString &message)
    {
        add(Diagnostic::Severity::Warning, at, object, message);
    }

    Diagnostics result() const { return m_result; }

private:
    QString m_fileName;
    Diagnostics m_result;
};

/// Reports the second and later use of a name, pointing at the later one.
class UniqueNames
{
public:
    UniqueNames(Findings &findings, const QString &what)
        : m_findings(findings)
        , m_what(what)
    { }

    void check(const QString &name, const SourceLocation &at, const QString &object)
    {
        if (name.isEmpty())
            return;
        const auto previous = m_seen.constFind(name);
        if (previous == m_seen.cend()) {
            m_seen.insert(name, at);
            return;
        }
        m_findings.error(at, object,
                         previous->isValid() ? tr("duplicate %1 '%2' (first used at line %3)")
                                                   .arg(m_what, name)
                                                   .arg(previous->line)
                                             : tr("duplicate %1 '%2'").arg(m_what, name));
    }

private:
    Findings &m_findings;
    QString m_what;
    QHash<QString, SourceLocation> m_seen;
};

void checkName(Findings &f, const QString &name, const SourceLocation &at, const QString &object,
               const QString &what)
{
    static const QRegularExpression allowed(QStringLiteral(R"(^[0-9A-Za-z_\-:]+$)"));
    if (name.isEmpty()) {
        f.error(at, object, tr("the %1 is empty").arg(what));
        return;
    }
    if (!allowed.match(name).hasMatch()) {
        f.error(
            at, object,
            tr("the %1 '%2' may only contain letters, digits, '_', '-' and ':'").arg(what, name));
    }
}

void checkEnum(Findings &f, const QString &value, const QStringList &allowed,
               const SourceLocation &at, const QString &object, const QString &what)
{
    if (allowed.contains(value))
        return;
    f.error(at, object,
            value.isEmpty() ? tr("the %1 is empty (expected one of %2)")
                                  .arg(what, allowed.join(QLatin1String(", ")))
                            : tr("unknown %1 '%2' (expected one of %3)")
                                  .arg(what, value, allowed.join(QLatin1String(", "))));
}

void checkBasicInfo(Findings &f, const RtcProfile &profile)
{
    const RtcBasicInfo &b = profile.basicInfo;
    const QString object = tr("component %1").arg(b.name);
    checkName(f, b.name, b.location, object, tr("component name"));
    checkEnum(f, b.componentType, rtcComponentTypes(), b.location, object, tr("component type"));
    checkEnum(f, b.activityType, rtcActivityTypes(), b.location, object, tr("activity type"));
    if (b.executionRate) {
        const auto rate = b.executionRateValue();
        if (!rate || *rate < 0) {
            f.error(b.location, object,
                    tr("the execution rate '%1' is not a number ≥ 0").arg(*b.executionRate));
        }
    }
    if (b.maxInstances) {
        const auto count = b.maxInstancesValue();
        if (!count || *count < 0) {
            f.error(b.location, object,
                    tr("the maximum number of instances '%1' is not an integer ≥ 0")
                        .arg(*b.maxInstances));
        }
    }
}

void checkId(Findings &f, const RtcProfile &profile)
{
    const QString object = tr("profile id");
    const auto id = RtcComponentId::parse(profile.id);
    if (!id) {
        f.error(
            profile.location, object,
            tr("malformed id '%1' (expected RTC:vendor:category:name:version)").arg(profile.id));
        return;
    }
    if (profile.id != profile.idFromBasicInfo()) {
        f.warning(profile.location, object,
                  tr("the id '%1' does not match the basic information (%2)")
                      .arg(profile.id, profile.idFromBasicInfo()));
    }
}

void checkActions(Findings &f, const RtcProfile &profile)
{
    for (RtcAction action : rtcAllActions()) {
        const auto &status = profile.actions[action];
        if (status && !parseBoolean(status->implemented)) {
            f.error(status->location, rtcActionKey(action),
                    tr("'implemented' is '%1', not true or false").arg(status->implemented));
        }
    }
}

void checkConfigurations(Findings &f, const RtcProfile &profile, UniqueNames &variables)
{
    UniqueNames names(f, tr("configuration name"));
    for (const RtcConfiguration &c : profile.configurations) {
        const QString object = tr("configuration %1").arg(c.name);
        checkName(f, c.name, c.location, object, tr("configuration name"));
        names.check(c.name, c.location, object);
        variables.check(c.variableName.value_or(QString()), c.location, object);
        const QString widget = c.widget().value_or(QString()).section(QLatin1Char('.'), 0, 0);
        if (widget == QLatin1String("radio")
            && !(c.constraint && isEnumerationConstraint(*c.constraint))) {
            f.error(c.location, object,
                    tr("a radio widget needs an enumeration constraint such as (a,b,c)"));
        }
    }
}

void checkDataPorts(Findings &f, const RtcProfile &profile, UniqueNames &ports,
                    UniqueNames &variables)
{
    for (const RtcDataPort &p : profile.dataPorts) {
        const QString object = tr("data port %1").arg(p.name);
        checkName(f, p.name, p.location, object, tr("port name"));
        ports.check(p.name, p.location, object);
        variables.check(p.variableName.value_or(QString()), p.location, object);
        checkEnum(f, p.portType, rtcPortTypes(), p.location, object, tr("port type"));
        checkEnum(f, p.position, rtcPositions(), p.location, object, tr("position"));
    }
}

void checkServicePorts(Findings &f, const RtcProfile &profile, UniqueNames &ports,
                       UniqueNames &variables)
{
    for (const RtcServicePort &p : profile.servicePorts) {
        const QString object = tr("service port %1").arg(p.name);
        checkName(f, p.name, p.location, object, tr("port name"));
        ports.check(p.name, p.location, object);
        checkEnum(f, p.position, rtcPositions(), p.location, object, tr("position"));
        UniqueNames interfaces(f, tr("interface name"));
        for (const RtcServiceInterface &i : p.interfaces) {
            const QString interfaceObject = tr("interface %1 of %2").arg(i.name, p.name);
            checkName(f, i.name, i.location, interfaceObject, tr("interface name"));
            interfaces.check(i.name, i.location, interfaceObject);
            variables.check(i.variableName.value_or(QString()), i.location, interfaceObject);
            checkEnum(f, i.direction, rtcDirections(), i.location, interfaceObject,
                      tr("direction"));
        }
    }
}

} // namespace

Diagnostics validateRtcProfile(const RtcProfile &profile, const QString &fileName)
{
    Findings findings(fileName);
    checkId(findings, profile);
    checkBasicInfo(findings, profile);
    checkActions(findings, profile);
    // Data and service ports share one name space in a component; variables share the class.
    UniqueNames ports(findings, tr("port name"));
    UniqueNames variables(findings, tr("variable name"));
    checkConfigurations(findings, profile, variables);
    checkDataPorts(findings, profile, ports, variables);
    checkServicePorts(findings, profile, ports, variables);
    return findings.result();
}

} // namespace Profile
