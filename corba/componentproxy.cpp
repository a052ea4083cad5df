// SPDX-License-Identifier: MIT
#include "componentproxy.h"

#include "corbacall.h"
#include "rtcconversion.h"

#include <functional>

namespace Corba {

using namespace Internal;

namespace {

RTC::RTObject_ptr component(const QString &ior, const QString &path)
{
    CORBA::Object_var object = toObject(ior, path);
    return RTC::RTObject::_unchecked_narrow(object.in());
}

SDOPackage::Configuration_ptr configuration(const QString &ior, const QString &path)
{
    RTC::RTObject_var rtc = component(ior, path);
    return call(path, [&] { return rtc->get_configuration(); });
}

// The context at rtshell's index: owned contexts first, then participating ones. The participating
// list is asked only for an index past the owned ones: the pollers read states in context 0 of
// every component every second, and this keeps that at two calls per component.
RTC::ExecutionContext_ptr context(RTC::RTObject_ptr rtc, int index, const QString &path)
{
    return call(path, [&] {
        RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
        const int ownedCount = int(owned->length());
        if (index >= 0 && index < ownedCount)
            return RTC::ExecutionContext::_duplicate(owned[CORBA::ULong(index)]);
        if (index >= ownedCount) {
            RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
            if (index < ownedCount + int(participating->length()))
                return RTC::ExecutionContext::_duplicate(
                    participating[CORBA::ULong(index - ownedCount)]);
        }
        throw Error(Error::Kind::NotFound,
                    QStringLiteral("%1: no execution context with index %2").arg(path).arg(index));
    });
}

ExecutionContextInfo contextInfo(RTC::RTObject_ptr rtc, RTC::ExecutionContext_ptr ec, bool owned)
{
    ExecutionContextInfo info;
    info.owned = owned;
    info.handle = int(rtc->get_context_handle(ec));
    info.kind = executionKindName(ec->get_kind());
    info.rate = ec->get_rate();
    info.running = ec->is_running();
    info.state = toLifeCycleState(ec->get_component_state(rtc));
    info.ior = toIor(ec);
    return info;
}

RTC::ExecutionContext_ptr contextAt(const QString &contextIor, const QString &path)
{
    CORBA::Object_var object = toObject(contextIor, path);
    if (CORBA::is_nil(object))
        throw Error(Error::Kind::BadPath,
                    QStringLiteral("%1: no execution context reference given").arg(path));
    return RTC::ExecutionContext::_unchecked_narrow(object.in());
}

bool listed(const RTC::ExecutionContextList &list, RTC::ExecutionContext_ptr ec)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (list[i]->_is_equivalent(ec))
            return true;
    }
    return false;
}

bool owns(RTC::RTObject_ptr rtc, RTC::ExecutionContext_ptr ec)
{
    RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
    return listed(owned.in(), ec);
}

bool participates(RTC::RTObject_ptr rtc, RTC::ExecutionContext_ptr ec)
{
    RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
    return listed(participating.in(), ec);
}

// A member that does not answer is still listed, by reference, so the view can say so.
ContextMember member(RTC::RTObject_ptr rtc)
{
    ContextMember result;
    if (CORBA::is_nil(rtc))
        return result;
    result.ior = toIor(rtc);
    try {
        RTC::ComponentProfile_var profile = rtc->get_component_profile();
        result.name = toQString(profile->instance_name.in());
    } catch (const CORBA::Exception &) {
        // Left unnamed: the view shows it as not answering.
    }
    return result;
}

// Owner and participants come from ExecutionContextService::get_profile; a plain
// ExecutionContext has no profile and leaves both empty.
void readMembers(ExecutionContextInfo &info, RTC::ExecutionContext_ptr ec)
{
    RTC::ExecutionContextService_var service = RTC::ExecutionContextService::_narrow(ec);
    if (CORBA::is_nil(service))
        return;
    RTC::ExecutionContextProfile_var profile = service->get_profile();
    info.owner = member(profile->owner.in());
    for (CORBA::ULong i = 0; i < profile->participants.length(); ++i) {
        RTC::RTObject_ptr participant = profile->participants[i].in();
        if (!CORBA::is_nil(profile->owner.in()) && participant->_is_equivalent(profile->owner.in()))
            continue;
        info.participants.push_back(member(participant));
    }
}

} // namespace

ComponentProxy::ComponentProxy(QString ior, QString path)
    : m_ior(std::move(ior))
    , m_path(std::move(path))
{ }

ComponentInfo ComponentProxy::profile() const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTC::ComponentProfile_var profile = rtc->get_component_profile();
        return toComponentInfo(profile.in());
    });
}

std::vector<PortInfo> ComponentProxy::ports() const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        std::vector<PortInfo> ports;
        RTC::PortServiceList_var list = rtc->get_ports();
        for (CORBA::ULong i = 0; i < list->length(); ++i) {
            RTC::PortProfile_var profile = list[i]->get_port_profile();
            ports.push_back(toPortInfo(profile.in()));
        }
        return ports;
    });
}

OrganizationInfo ComponentProxy::organizations() const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        // An SDO names itself by its id; a member that does not answer is left out.
        const auto sdoName = [](SDOPackage::SDO_ptr sdo) -> QString {
            try {
                CORBA::String_var id = sdo->get_sdo_id();
                return QString::fromUtf8(id.in());
            } catch (const CORBA::Exception &) {
                return QString();
            }
        };
        OrganizationInfo info;
        SDOPackage::OrganizationList_var owned = rtc->get_owned_organizations();
        info.composite = owned->length() > 0;
        for (CORBA::ULong i = 0; i < owned->length(); ++i) {
            SDOPackage::SDOList_var members = owned[i]->get_members();
            for (CORBA::ULong j = 0; j < members->length(); ++j) {
                const QString name = sdoName(members[j]);
                if (!name.isEmpty())
                    info.members.append(name);
            }
        }
        SDOPackage::OrganizationList_var joined = rtc->get_organizations();
        for (CORBA::ULong i = 0; i < joined->length(); ++i) {
            SDOPackage::SDOSystemElement_var owner = joined[i]->get_owner();
            SDOPackage::SDO_var sdo = SDOPackage::SDO::_narrow(owner);
            const QString name = CORBA::is_nil(sdo) ? QString() : sdoName(sdo);
            if (!name.isEmpty())
                info.parents.append(name);
        }
        return info;
    });
}

PortInfo ComponentProxy::port(const QString &name) const
{
    for (PortInfo &port : ports()) {
        if (port.name == name || port.shortName() == name)
            return port;
    }
    throw Error(Error::Kind::NotFound, QStringLiteral("%1: no port named '%2'").arg(m_path, name));
}

std::vector<ExecutionContextInfo> ComponentProxy::executionContexts(ContextDetail detail) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        std::vector<ExecutionContextInfo> contexts;
        const auto add = [&](RTC::ExecutionContext_ptr ec, bool owned) {
            contexts.push_back(contextInfo(rtc.in(), ec, owned));
            if (detail == ContextDetail::Members)
                readMembers(contexts.back(), ec);
        };
        RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
        if (detail == ContextDetail::Saved) {
            for (CORBA::ULong i = 0; i < owned->length(); ++i) {
                ExecutionContextInfo info;
                info.handle = int(rtc->get_context_handle(owned[i]));
                info.kind = executionKindName(owned[i]->get_kind());
                info.rate = owned[i]->get_rate();
                contexts.push_back(info);
            }
            return contexts;
        }
        for (CORBA::ULong i = 0; i < owned->length(); ++i)
            add(owned[i].in(), true);
        RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
        for (CORBA::ULong i = 0; i < participating->length(); ++i)
            add(participating[i].in(), false);
        return contexts;
    });
}

void ComponentProxy::attachContext(const QString &contextIor) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = contextAt(contextIor, m_path);
    callServed(m_path, m_ior, [&] {
        if (owns(rtc.in(), ec.in()))
            throw Error(Error::Kind::Refused,
                        QStringLiteral("%1: owns this execution context already").arg(m_path));
        if (participates(rtc.in(), ec.in()))
            throw Error(
                Error::Kind::Refused,
                QStringLiteral("%1: takes part in this execution context already").arg(m_path));
    });
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->add_component(rtc.in())); }), m_path,
                    QStringLiteral("add_component"));
    // OpenRTM-aist's contexts call attach_context from add_component; others leave it to the
    // tool, and without it the component would not list the context.
    callServed(m_path, m_ior, [&] {
        if (!participates(rtc.in(), ec.in()))
            rtc->attach_context(ec.in());
    });
}

void ComponentProxy::detachContext(const QString &contextIor) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = contextAt(contextIor, m_path);
    callServed(m_path, m_ior, [&] {
        if (owns(rtc.in(), ec.in()))
            throw Error(
                Error::Kind::Refused,
                QStringLiteral("%1: cannot leave the execution context it owns").arg(m_path));
        if (!participates(rtc.in(), ec.in()))
            throw Error(
                Error::Kind::NotFound,
                QStringLiteral("%1: does not take part in this execution context").arg(m_path));
    });
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->remove_component(rtc.in())); }), m_path,
                    QStringLiteral("remove_component"));
    // As with attaching: a context that did not call detach_context leaves it to the tool.
    callServed(m_path, m_ior, [&] {
        if (!participates(rtc.in(), ec.in()))
            return;
        checkReturnCode(int(rtc->detach_context(rtc->get_context_handle(ec.in()))), m_path,
                        QStringLiteral("detach_context"));
    });
}

LifeCycleState ComponentProxy::state(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    return callServed(m_path, m_ior, [&] { return toLifeCycleState(ec->get_component_state(rtc.in())); });
}

void ComponentProxy::activate(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->activate_component(rtc.in())); }), m_path,
                    QStringLiteral("activate"));
}

void ComponentProxy::deactivate(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->deactivate_component(rtc.in())); }), m_path,
                    QStringLiteral("deactivate"));
}

void ComponentProxy::reset(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->reset_component(rtc.in())); }), m_path,
                    QStringLiteral("reset"));
}

void ComponentProxy::exit() const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(rtc->exit()); }), m_path, QStringLiteral("exit"));
}

void ComponentProxy::startContext(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->start()); }), m_path,
                    QStringLiteral("start"));
}

void ComponentProxy::stopContext(int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->stop()); }), m_path, QStringLiteral("stop"));
}

void ComponentProxy::setRate(double rate, int ecIndex) const
{
    RTC::RTObject_var rtc = component(m_ior, m_path);
    RTC::ExecutionContext_var ec = context(rtc.in(), ecIndex, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(ec->set_rate(rate)); }), m_path,
                    QStringLiteral("set_rate"));
}

std::vector<ConfigurationSet> ComponentProxy::configurationSets() const
{
    return configurationSets(nullptr);
}

std::vector<ConfigurationSet> ComponentProxy::configurationSets(QString *activeSet) const
{
    SDOPackage::Configuration_var conf = configuration(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        SDOPackage::ConfigurationSetList_var sets = conf->get_configuration_sets();
        std::vector<ConfigurationSet> result;
        for (CORBA::ULong i = 0; i < sets->length(); ++i)
            result.push_back(toConfigurationSet(sets[i]));
        if (!activeSet)
            return result;
        activeSet->clear();
        if (!result.empty()) {
            try {
                SDOPackage::ConfigurationSet_var set = conf->get_active_configuration_set();
                *activeSet = toQString(set->id.in());
            } catch (const SDOPackage::NotAvailable &) {
                // None active: written, not activated since.
            }
        }
        return result;
    });
}

QString ComponentProxy::activeConfigurationSet() const
{
    SDOPackage::Configuration_var conf = configuration(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        try {
            SDOPackage::ConfigurationSet_var set = conf->get_active_configuration_set();
            return toQString(set->id.in());
        } catch (const SDOPackage::NotAvailable &) {
            return QString();
        }
    });
}

ConfigurationSet ComponentProxy::configurationSet(const QString &id) const
{
    for (ConfigurationSet &set : configurationSets()) {
        if (set.id == id)
            return set;
    }
    throw Error(Error::Kind::NotFound,
                QStringLiteral("%1: no configuration set '%2'").arg(m_path, id));
}

namespace {

/// Runs @p write (false: refused, reported with @p refusal) and activates again the set that was
/// active before it.
void writeConfiguration(const ComponentProxy &proxy,
                        const std::function<bool(SDOPackage::Configuration_ptr)> &write,
                        const QString &refusal)
{
    // Asked before the write: from the write until an activation there is no active set.
    const QString active = proxy.activeConfigurationSet();
    SDOPackage::Configuration_var conf = configuration(proxy.ior(), proxy.path());
    if (!call(proxy.path(), [&] { return write(conf.in()); }))
        throw Error(Error::Kind::Refused, QStringLiteral("%1: %2").arg(proxy.path(), refusal));
    if (!active.isEmpty())
        proxy.activateConfigurationSet(active);
}

} // namespace

void ComponentProxy::addConfigurationSet(const ConfigurationSet &set) const
{
    writeConfiguration(*this,
        [&](SDOPackage::Configuration_ptr conf) { return conf->add_configuration_set(toSdoConfigurationSet(set)); },
        QStringLiteral("configuration set '%1' was not added").arg(set.id));
}

void ComponentProxy::setConfigurationSetValues(const ConfigurationSet &set) const
{
    writeConfiguration(*this,
        [&](SDOPackage::Configuration_ptr conf) {
            return conf->set_configuration_set_values(toSdoConfigurationSet(set));
        },
        QStringLiteral("configuration set '%1' was not written").arg(set.id));
}

void ComponentProxy::removeConfigurationSet(const QString &id) const
{
    const QByteArray utf8 = id.toUtf8();
    writeConfiguration(*this,
        [&](SDOPackage::Configuration_ptr conf) { return conf->remove_configuration_set(utf8.constData()); },
        QStringLiteral("configuration set '%1' was not removed").arg(id));
}

void ComponentProxy::activateConfigurationSet(const QString &id) const
{
    SDOPackage::Configuration_var conf = configuration(m_ior, m_path);
    const QByteArray utf8 = id.toUtf8();
    const bool ok
        = callServed(m_path, m_ior, [&] { return conf->activate_configuration_set(utf8.constData()); });
    if (!ok)
        throw Error(Error::Kind::Refused,
                    QStringLiteral("%1: configuration set '%2' was not activated").arg(m_path, id));
}

QString ComponentProxy::parameter(const QString &setId, const QString &name) const
{
    const ConfigurationSet set = configurationSet(setId);
    if (!hasProperty(set.data, name))
        throw Error(Error::Kind::NotFound,
                    QStringLiteral("%1: no parameter '%2' in set '%3'").arg(m_path, name, setId));
    return propertyValue(set.data, name);
}

void ComponentProxy::setParameter(const QString &setId, const QString &name,
                                  const QString &value) const
{
    ConfigurationSet set = configurationSet(setId);
    if (!hasProperty(set.data, name))
        throw Error(Error::Kind::NotFound,
                    QStringLiteral("%1: no parameter '%2' in set '%3'").arg(m_path, name, setId));
    setProperty(set.data, name, value);
    writeConfiguration(*this,
        [&](SDOPackage::Configuration_ptr conf) {
            return conf->set_configuration_set_values(toSdoConfigurationSet(set));
        },
        QStringLiteral("parameter '%1' was not set").arg(name));
}

} // namespace Corba
