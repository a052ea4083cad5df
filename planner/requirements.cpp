// SPDX-License-Identifier: MIT
#include "requirements.h"

#include "nodefacts.h"
#include "rtcprofile.h"
#include "rtsprofile.h"

#include <QCoreApplication>
namespace Planner {

namespace {

/// The properties that state requirements, the type's first and the component's over them.
using PropertyMap = QMap<QString, QString>;

QString typeNameOf(const QString &typeId)
{
    const QStringList parts = typeId.split(QLatin1Char(':'));
    return parts.size() >= 4 ? parts.at(3) : typeId;
}

const Profile::RtcProfile *profileOf(const Profile::RtsComponent &component,
                                     const QHash<QString, Profile::RtcProfile> &typeProfiles)
{
    auto it = typeProfiles.constFind(component.id);
    if (it == typeProfiles.constEnd())
        it = typeProfiles.constFind(typeNameOf(component.id));
    return it == typeProfiles.constEnd() ? nullptr : &*it;
}

void addRtcProperties(const Profile::RtcProperties &properties, PropertyMap *out)
{
    for (const Profile::RtcProperty &p : properties) {
        if (p.name.startsWith(QLatin1String("deploy.")))
            out->insert(p.name, p.value.value_or(QString()));
    }
}

void readProfile(const Profile::RtcProfile &profile, ComponentRequirements *r,
                 PropertyMap *properties)
{
    addRtcProperties(profile.basicInfo.properties, properties);
    if (!profile.language)
        return;
    r->language = profile.language->kind.trimmed();
    addRtcProperties(profile.language->properties, properties);
    for (const Profile::RtcTargetEnvironment &target : profile.language->targets) {
        if (target.os && !target.os->trimmed().isEmpty() && !r->oses.contains(target.os->trimmed()))
            r->oses << target.os->trimmed();
        for (const QString &version : target.osVersions)
            r->osVersions << version.trimmed();
        for (const QString &cpu : target.cpus)
            r->architectures << cpu.trimmed();
    }
    r->osVersions.removeAll(QString());
    r->architectures.removeAll(QString());
}

void applyProperties(const PropertyMap &properties, const QString &instance,
                     ComponentRequirements *r, QStringList *warnings)
{
    for (auto it = properties.constBegin(); it != properties.constEnd(); ++it) {
        const QString &key = it.key();
        const QString value = it.value().trimmed();
        if (key == Key::Devices) {
            r->devices = splitFactList(value);
        } else if (key == Key::CpuShare) {
            bool ok = false;
            const double share = value.toDouble(&ok);
            if (!ok || share < 0)
                *warnings << QCoreApplication::translate("Planner", "%1: %2 '%3' is not a number of CPUs; ignored")
                                 .arg(instance, key, value);
            else
                r->cpuShare = share;
        } else if (key.startsWith(Key::NodeFactPrefix) && key.size() > Key::NodeFactPrefix.size()) {
            r->nodeFacts.insert(key.mid(Key::NodeFactPrefix.size()), value);
        } else if (key == Key::Process) {
            r->process = value;
        } else if (key == Key::Pin) {
            r->pinnedNode = value;
        }
    }
}

ComponentRequirements componentRequirements(const Profile::RtsComponent &component,
                                            const QHash<QString, Profile::RtcProfile> &typeProfiles,
                                            QStringList *unprofiled, QStringList *warnings)
{
    ComponentRequirements r;
    r.instanceName = component.instanceName;
    r.typeId = component.id;
    r.typeName = typeNameOf(component.id);
    PropertyMap properties;
    if (const Profile::RtcProfile *profile = profileOf(component, typeProfiles))
        readProfile(*profile, &r, &properties);
    else if (!unprofiled->contains(r.typeName))
        *unprofiled << r.typeName;
    for (const Profile::RtsProperty &p : component.properties) {
        if (p.name.startsWith(QLatin1String("deploy.")))
            properties.insert(p.name, p.value.value_or(QString()));
    }
    applyProperties(properties, component.instanceName, &r, warnings);
    return r;
}

bool sharesContext(const Profile::RtsComponent &component)
{
    const QString type = component.compositeType.value_or(QString());
    return !component.participants.isEmpty() && type != QLatin1String("None")
        && type != QLatin1String("Grouping") && !type.isEmpty();
}

/// Members of composites that share an execution context get the composite's process.
void groupComposites(const Profile::RtsProfile &system, QList<ComponentRequirements> *components)
{
    QHash<QString, int> index;
    for (int i = 0; i < components->size(); ++i)
        index.insert(components->at(i).instanceName, i);
    for (const Profile::RtsComponent &composite : system.components) {
        if (!sharesContext(composite))
            continue;
        ComponentRequirements &owner = (*components)[index.value(composite.instanceName)];
        if (owner.process.isEmpty())
            owner.process = composite.instanceName;
        for (const Profile::RtsParticipant &member : composite.participants) {
            const auto it = index.constFind(member.participant.instanceName);
            if (it != index.constEnd())
                (*components)[*it].process = owner.process;
        }
    }
}

/// The rate data leaves @p instance at: its first execution context's, else its type's.
double componentRate(const Profile::RtsProfile &system, const QString &instance,
                     const QHash<QString, Profile::RtcProfile> &typeProfiles)
{
    const Profile::RtsComponent *component = system.component(instance);
    if (!component)
        return 0;
    for (const Profile::RtsExecutionContext &ec : component->executionContexts) {
        if (const std::optional<double> rate = ec.rateValue())
            return *rate;
    }
    const Profile::RtcProfile *profile = profileOf(*component, typeProfiles);
    return profile ? profile->basicInfo.executionRateValue().value_or(0) : 0;
}

QList<Link> readLinks(const Profile::RtsProfile &system,
                      const QHash<QString, Profile::RtcProfile> &typeProfiles)
{
    QList<Link> links;
    for (const Profile::RtsDataPortConnector &connector : system.dataPortConnectors) {
        Link link {connector.source.instanceName, connector.target.instanceName, 0};
        bool ok = false;
        const double rate = Profile::rtsPropertyValue(connector.properties, Key::Rate)
                                .value_or(QString())
                                .toDouble(&ok);
        link.rate = ok ? rate : componentRate(system, link.source, typeProfiles);
        links << link;
    }
    return links;
}

} // namespace

SystemRequirements readRequirements(const Profile::RtsProfile &system,
                                    const QHash<QString, Profile::RtcProfile> &typeProfiles)
{
    SystemRequirements result;
    QStringList unprofiled;
    for (const Profile::RtsComponent &component : system.components)
        result.components << componentRequirements(component, typeProfiles, &unprofiled,
                                                   &result.warnings);
    if (!unprofiled.isEmpty())
        result.warnings << QCoreApplication::translate("Planner", "no RTC profile of %1: only the components' own deploy.* "
                                          "properties are required")
                               .arg(unprofiled.join(QStringLiteral(", ")));
    groupComposites(system, &result.components);
    result.links = readLinks(system, typeProfiles);
    return result;
}

void addTypeProfile(const Profile::RtcProfile &profile,
                    QHash<QString, Profile::RtcProfile> *typeProfiles)
{
    typeProfiles->insert(profile.id, profile);
    typeProfiles->insert(profile.basicInfo.name, profile);
}

} // namespace Planner
