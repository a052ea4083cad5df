// SPDX-License-Identifier: MIT
// PeriodicECSharedComposite: members run on the composite's periodic execution context, and
// their exported ports are listed as the composite's.
#include <rtm/ConfigurationListener.h>
#include <rtm/Manager.h>
#include <rtm/PeriodicECSharedComposite.h>

#include "sdkinternal.h"

#include <corbautil.h>
#include <manager.h>
#include <properties.h>

#include <algorithm>
#include <iterator>

namespace {

/// Parses the `members` parameter: a comma-separated list.
bool toMemberList(std::vector<std::string> &members, const char *text)
{
    members = coil::split(text != nullptr ? text : "", ",", true);
    return true;
}

/// The port names of an `exported_ports` value, as the manager and SDO configuration store them.
std::vector<std::string> exportedPortNames(const std::string &text)
{
    return coil::split(Runtime::exportedPortList(text), ",", true);
}

/// This process's component called @p name; nil when there is none.
RTC::RTObject_ptr localComponent(RTC::Manager *manager, const std::string &name)
{
    Runtime::Manager *runtime = manager != nullptr ? manager->runtime() : nullptr;
    if (runtime == nullptr)
        return RTC::RTObject::_nil();
    const RTC::RTCList found = runtime->componentsByName(name);
    return found.length() > 0 ? RTC::RTObject::_duplicate(found[0]) : RTC::RTObject::_nil();
}

/// The members of @p rtobj's owned organizations (a nested composite's); empty for a plain component.
std::vector<RTC::RTObject_var> nestedMembers(RTC::RTObject_ptr rtobj, bool *isComposite)
{
    std::vector<RTC::RTObject_var> members;
    *isComposite = false;
    SDOPackage::OrganizationList_var organizations = rtobj->get_owned_organizations();
    for (CORBA::ULong i = 0; i < organizations->length(); ++i) {
        *isComposite = true;
        SDOPackage::SDOList_var sdos = organizations[i]->get_members();
        for (CORBA::ULong j = 0; j < sdos->length(); ++j) {
            RTC::RTObject_var member = RTC::RTObject::_narrow(sdos[j]);
            if (!CORBA::is_nil(member))
                members.push_back(member);
        }
    }
    return members;
}

/// Calls @p change for @p rtobj, or for the plain components inside it when it is a composite.
template <typename Change>
void forEachPlainComponent(RTC::RTObject_ptr rtobj, Change change)
{
    if (CORBA::is_nil(rtobj))
        return;
    try {
        bool isComposite = false;
        const std::vector<RTC::RTObject_var> members = nestedMembers(rtobj, &isComposite);
        if (!isComposite) {
            change(rtobj);
            return;
        }
        for (const RTC::RTObject_var &member : members)
            forEachPlainComponent(member.in(), change);
    } catch (const CORBA::Exception &) {
        // A member whose process is gone is no longer driven.
    }
}

/// Keeps the composite's exported ports in step with its configuration sets.
class ExportedPortsUpdate : public RTC::ConfigurationSetListener
{
public:
    ExportedPortsUpdate(RTC::RTObject_impl *composite, SDOPackage::PeriodicECOrganization *organization)
        : m_composite(composite)
        , m_organization(organization)
    {
    }
    void operator()(const coil::Properties &config_set) override
    {
        // OpenRTM reads the default set's value from the component's properties.
        if (std::string(config_set.getName()) != "default")
            return;
        m_composite->getProperties()["conf.default.exported_ports"] = config_set.getProperty("exported_ports");
        m_organization->updateDelegatedPorts();
    }

private:
    RTC::RTObject_impl *m_composite;
    SDOPackage::PeriodicECOrganization *m_organization;
};

const char *const compositeSpec[] = {
    "implementation_id", "PeriodicECSharedComposite",
    "type_name", "PeriodicECSharedComposite",
    "description", "PeriodicECSharedComposite",
    "version", "1.0",
    "vendor", "jp.go.aist",
    "category", "composite.PeriodicECShared",
    "activity_type", "DataFlowComponent",
    "max_instance", "0",
    "language", "C++",
    "lang_type", "compile",
    "exported_ports", "",
    "conf.default.members", "",
    "conf.default.exported_ports", "",
    "",
};

} // namespace

namespace SDOPackage {

PeriodicECOrganization::Member::Member(RTC::RTObject_ptr rtobj)
    : rtobj_(RTC::RTObject::_duplicate(rtobj))
    , profile_(rtobj->get_component_profile())
    , eclist_(rtobj->get_owned_contexts())
    , config_(rtobj->get_configuration())
{
}

PeriodicECOrganization::PeriodicECOrganization(::RTC::RTObject_impl *rtobj, SDOSystemElement_ptr sdo)
    : ::Runtime::Organization(PortableServer::POA_var(RTC::Sdk::rootPoa()).in(), sdo)
    , rtclog("PeriodicECOrganization")
    , m_rtobj(rtobj)
    , m_ec(RTC::ExecutionContext::_nil())
{
    publishProperties();
}

PeriodicECOrganization::~PeriodicECOrganization() = default;

Organization_ptr PeriodicECOrganization::getObjRef()
{
    return reference();
}

CORBA::Boolean PeriodicECOrganization::add_members(const SDOList &sdo_list)
{
    std::lock_guard<std::recursive_mutex> lock(m_memberMutex);
    updateExportedPortsList();
    SDOList joined;
    for (CORBA::ULong i = 0; i < sdo_list.length(); ++i) {
        OpenRTM::DataFlowComponent_var dfc;
        if (!sdoToDFC(sdo_list[i], dfc.out()) || isMemberOrOwner(dfc.in()))
            continue;
        try {
            Member member(dfc.in());
            stopOwnedEC(member);
            addOrganizationToTarget(member);
            addParticipantToEC(member);
            addPort(member, m_expPorts);
            m_rtcMembers.push_back(member);
        } catch (const CORBA::Exception &) {
            // Its profile could not be read (the member went away): it does not join.
            RTC_WARN(("a member did not answer and was left out"));
            continue;
        }
        const CORBA::ULong n = joined.length();
        joined.length(n + 1);
        joined[n] = SDO::_duplicate(sdo_list[i]);
    }
    const CORBA::Boolean result = ::Runtime::Organization::add_members(joined);
    publishProperties();
    return result;
}

CORBA::Boolean PeriodicECOrganization::set_members(const SDOList &sdo_list)
{
    std::lock_guard<std::recursive_mutex> lock(m_memberMutex);
    removeAllMembers();
    return add_members(sdo_list);
}

CORBA::Boolean PeriodicECOrganization::remove_member(const char *id)
{
    if (id == nullptr)
        throw InvalidParameter("nil member id");
    std::lock_guard<std::recursive_mutex> lock(m_memberMutex);
    for (MemIt it = m_rtcMembers.begin(); it != m_rtcMembers.end(); ++it) {
        if (std::string(it->profile_->instance_name.in()) != id)
            continue;
        removePort(*it, m_expPorts);
        m_rtobj->getProperties()["conf.default.exported_ports"] = coil::flatten(m_expPorts, ",");
        removeParticipantFromEC(*it);
        removeOrganizationFromTarget(*it);
        startOwnedEC(*it);
        m_rtcMembers.erase(it);
        break;
    }
    const CORBA::Boolean result = ::Runtime::Organization::remove_member(id);
    publishProperties();
    return result;
}

void PeriodicECOrganization::removeAllMembers()
{
    std::lock_guard<std::recursive_mutex> lock(m_memberMutex);
    updateExportedPortsList();
    for (Member &member : m_rtcMembers) {
        removePort(member, m_expPorts);
        removeParticipantFromEC(member);
        removeOrganizationFromTarget(member);
        startOwnedEC(member);
    }
    m_rtcMembers.clear();
    m_expPorts.clear();
    ::Runtime::Organization::set_members(SDOList());
    publishProperties();
}

bool PeriodicECOrganization::sdoToDFC(SDO_ptr sdo, ::OpenRTM::DataFlowComponent_ptr &dfc)
{
    if (CORBA::is_nil(sdo))
        return false;
    try {
        dfc = OpenRTM::DataFlowComponent::_narrow(sdo);
    } catch (const CORBA::Exception &) {
        return false;
    }
    return !CORBA::is_nil(dfc);
}

void PeriodicECOrganization::stopOwnedEC(Member &member)
{
    // A context already stopped answers PRECONDITION_NOT_MET, which changes nothing here.
    for (CORBA::ULong i = 0; i < member.eclist_->length(); ++i) {
        try {
            member.eclist_[i]->stop();
        } catch (const CORBA::Exception &) {
        }
    }
}

void PeriodicECOrganization::startOwnedEC(Member &member)
{
    for (CORBA::ULong i = 0; i < member.eclist_->length(); ++i) {
        try {
            member.eclist_[i]->start();
        } catch (const CORBA::Exception &) {
        }
    }
}

void PeriodicECOrganization::addOrganizationToTarget(Member &member)
{
    if (CORBA::is_nil(member.config_))
        return;
    try {
        Organization_var self = reference();
        member.config_->add_organization(self);
    } catch (const CORBA::Exception &) {
        RTC_WARN(("%s does not accept the organization", member.profile_->instance_name.in()));
    }
}

void PeriodicECOrganization::removeOrganizationFromTarget(Member &member)
{
    if (CORBA::is_nil(member.config_))
        return;
    try {
        member.config_->remove_organization(id().c_str());
    } catch (const CORBA::Exception &) {
    }
}

void PeriodicECOrganization::addRTCToEC(RTC::RTObject_ptr rtobj)
{
    forEachPlainComponent(rtobj, [this](RTC::RTObject_ptr plain) { m_ec->add_component(plain); });
}

void PeriodicECOrganization::addParticipantToEC(Member &member)
{
    if (CORBA::is_nil(m_ec)) {
        RTC::ExecutionContextList_var contexts = m_rtobj->get_owned_contexts();
        if (contexts->length() == 0) {
            RTC_ERROR(("the composite has no execution context for %s", member.profile_->instance_name.in()));
            return;
        }
        m_ec = RTC::ExecutionContext::_duplicate(contexts[CORBA::ULong(0)]);
    }
    addRTCToEC(member.rtobj_.in());
}

void PeriodicECOrganization::removeParticipantFromEC(Member &member)
{
    if (CORBA::is_nil(m_ec))
        return;
    forEachPlainComponent(member.rtobj_.in(), [this](RTC::RTObject_ptr plain) {
        // An active participant cannot leave: it stops first, so that it can later run (and
        // finalize) on its own context again.
        if (m_ec->get_component_state(plain) == RTC::ACTIVE_STATE)
            m_ec->deactivate_component(plain);
        m_ec->remove_component(plain);
    });
}

void PeriodicECOrganization::addPort(Member &member, PortList &portlist)
{
    if (portlist.empty())
        return;
    const RTC::PortProfileList &ports = member.profile_->port_profiles;
    for (CORBA::ULong i = 0; i < ports.length(); ++i) {
        const std::string name(ports[i].name.in());
        if (std::find(portlist.begin(), portlist.end(), name) == portlist.end())
            continue;
        m_rtobj->addPortReference(ports[i].port_ref);
        RTC_DEBUG(("exported port %s", name.c_str()));
    }
}

void PeriodicECOrganization::removePort(Member &member, PortList &portlist)
{
    if (portlist.empty())
        return;
    const RTC::PortProfileList &ports = member.profile_->port_profiles;
    for (CORBA::ULong i = 0; i < ports.length(); ++i) {
        const std::string name(ports[i].name.in());
        auto pos = std::find(portlist.begin(), portlist.end(), name);
        if (pos == portlist.end())
            continue;
        m_rtobj->removePortReference(ports[i].port_ref);
        portlist.erase(pos);
    }
}

void PeriodicECOrganization::updateExportedPortsList()
{
    coil::Properties &properties = m_rtobj->getProperties();
    std::string names = properties.getProperty("conf.default.exported_ports");
    if (coil::eraseBlank(names).empty())
        names = properties.getProperty("exported_ports");
    m_expPorts = exportedPortNames(names);
}

void PeriodicECOrganization::updateDelegatedPorts()
{
    std::lock_guard<std::recursive_mutex> lock(m_memberMutex);
    PortList oldPorts = m_expPorts;
    std::sort(oldPorts.begin(), oldPorts.end());
    PortList newPorts = exportedPortNames(m_rtobj->getProperties().getProperty("conf.default.exported_ports"));
    std::sort(newPorts.begin(), newPorts.end());
    PortList removed;
    PortList added;
    std::set_difference(oldPorts.begin(), oldPorts.end(), newPorts.begin(), newPorts.end(),
                        std::back_inserter(removed));
    std::set_difference(newPorts.begin(), newPorts.end(), oldPorts.begin(), oldPorts.end(),
                        std::back_inserter(added));
    for (Member &member : m_rtcMembers) {
        removePort(member, removed);
        addPort(member, added);
    }
    m_expPorts = newPorts;
    publishProperties();
}

bool PeriodicECOrganization::isMemberOrOwner(RTC::RTObject_ptr rtobj)
{
    // Joining twice would stop and attach it twice; the composite itself must keep its context.
    try {
        if (rtobj->_is_equivalent(RTC::RTObject_var(m_rtobj->getObjRef())))
            return true;
        for (const Member &member : m_rtcMembers) {
            if (member.rtobj_->_is_equivalent(rtobj))
                return true;
        }
    } catch (const CORBA::Exception &) {
    }
    return false;
}

void PeriodicECOrganization::publishProperties()
{
    std::vector<std::string> names;
    for (const Member &member : m_rtcMembers)
        names.push_back(member.profile_->instance_name.in());
    setProperty("members", coil::flatten(names, ","));
    setProperty("exported_ports", coil::flatten(m_expPorts, ","));
}

} // namespace SDOPackage

namespace RTC {

PeriodicECSharedComposite::PeriodicECSharedComposite(Manager *manager)
    : RTObject_impl(manager)
    , m_org(nullptr)
{
    bindParameter("members", m_members, "", toMemberList);
    // The composite's context changes its members' states from its own thread: transitions
    // must not wait for themselves.
    m_properties["exec_cxt.periodic.sync_transition"] = "NO";
    m_properties["exec_cxt.periodic.sync_activation"] = "NO";
    m_properties["exec_cxt.periodic.sync_deactivation"] = "NO";
    m_properties["exec_cxt.periodic.sync_reset"] = "NO";
}

PeriodicECSharedComposite::~PeriodicECSharedComposite() = default;

ReturnCode_t PeriodicECSharedComposite::initialize()
{
    if (m_org == nullptr) {
        CORBA::Object_var self = getObjRef();
        m_ref = OpenRTM::DataFlowComponent::_narrow(self);
        m_org = new SDOPackage::PeriodicECOrganization(this, m_ref.in());
        addConfigurationSetListener(ConfigurationSetListenerType::ON_SET_CONFIG_SET,
                                    new ExportedPortsUpdate(this, m_org));
        addConfigurationSetListener(ConfigurationSetListenerType::ON_ADD_CONFIG_SET,
                                    new ExportedPortsUpdate(this, m_org));
    }
    const ReturnCode_t result = RTObject_impl::initialize();
    if (result != RTC_OK) {
        Runtime::releaseServant(m_pPOA, m_org);
        m_org = nullptr;
        return result;
    }
    // Members join now that the composite's own context exists (it is made after onInitialize).
    SDOPackage::SDOList sdos;
    for (const std::string &name : m_members) {
        RTObject_var member = localComponent(m_pManager, name);
        if (CORBA::is_nil(member))
            continue; // gone since onInitialize
        const CORBA::ULong n = sdos.length();
        sdos.length(n + 1);
        sdos[n] = SDOPackage::SDO::_duplicate(member.in());
    }
    try {
        m_org->set_members(sdos);
    } catch (const CORBA::Exception &) {
        RTC_ERROR(("the members could not join"));
    }
    return RTC_OK;
}

ReturnCode_t PeriodicECSharedComposite::onInitialize()
{
    const std::string active = m_properties.getProperty("configuration.active_config", "default");
    m_configsets.update(m_configsets.haveConfig(active.c_str()) ? active.c_str() : "default");

    std::vector<std::string> names;
    std::vector<std::string> unknown;
    bool self = false;
    for (const std::string &entry : m_members) {
        const std::string name = coil::eraseBothEndsBlank(coil::replaceString(entry, "|", ""));
        if (name.empty())
            continue;
        names.push_back(name);
        if (name == getInstanceName())
            self = true;
        else if (CORBA::is_nil(RTObject_var(localComponent(m_pManager, name))))
            unknown.push_back(name);
    }
    m_members = names;
    if (self || !unknown.empty()) {
        const std::string reason = self ? std::string("a composite cannot be its own member")
                                        : "no component named '" + coil::flatten(unknown, "', '")
                                              + "' to be a member of " + getInstanceName();
        RTC_ERROR(("%s", reason.c_str()));
        setInitializeError(reason);
        return RTC_ERROR;
    }
    return RTC_OK;
}

ReturnCode_t PeriodicECSharedComposite::onActivated(RTC::UniqueId /*exec_handle*/)
{
    if (m_org == nullptr)
        return RTC_OK;
    const SDOPackage::SDOList sdos = m_org->members();
    for (CORBA::ULong i = 0; i < sdos.length(); ++i) {
        RTObject_var member = ::RTC::RTObject::_narrow(sdos[i]);
        activateChildComp(member.in());
    }
    RTC_INFO(("%u member(s) activated", unsigned(sdos.length())));
    return RTC_OK;
}

void PeriodicECSharedComposite::activateChildComp(const RTC::RTObject_ptr rtobj)
{
    ExecutionContextList_var contexts = get_owned_contexts();
    if (contexts->length() == 0)
        return;
    ExecutionContext_var context = ExecutionContext::_duplicate(contexts[CORBA::ULong(0)]);
    forEachPlainComponent(rtobj, [&context](RTObject_ptr plain) { context->activate_component(plain); });
}

ReturnCode_t PeriodicECSharedComposite::onDeactivated(RTC::UniqueId /*exec_handle*/)
{
    if (m_org == nullptr)
        return RTC_OK;
    const SDOPackage::SDOList sdos = m_org->members();
    for (CORBA::ULong i = 0; i < sdos.length(); ++i) {
        RTObject_var member = ::RTC::RTObject::_narrow(sdos[i]);
        deactivateChildComp(member.in());
    }
    return RTC_OK;
}

void PeriodicECSharedComposite::deactivateChildComp(const RTC::RTObject_ptr rtobj)
{
    ExecutionContextList_var contexts = get_owned_contexts();
    if (contexts->length() == 0)
        return;
    ExecutionContext_var context = ExecutionContext::_duplicate(contexts[CORBA::ULong(0)]);
    forEachPlainComponent(rtobj, [&context](RTObject_ptr plain) { context->deactivate_component(plain); });
}

ReturnCode_t PeriodicECSharedComposite::onReset(RTC::UniqueId /*exec_handle*/)
{
    if (m_org == nullptr)
        return RTC_OK;
    const SDOPackage::SDOList sdos = m_org->members();
    for (CORBA::ULong i = 0; i < sdos.length(); ++i) {
        RTObject_var member = ::RTC::RTObject::_narrow(sdos[i]);
        resetChildComp(member.in());
    }
    return RTC_OK;
}

void PeriodicECSharedComposite::resetChildComp(const RTC::RTObject_ptr rtobj)
{
    ExecutionContextList_var contexts = get_owned_contexts();
    if (contexts->length() == 0)
        return;
    ExecutionContext_var context = ExecutionContext::_duplicate(contexts[CORBA::ULong(0)]);
    forEachPlainComponent(rtobj, [&context](RTObject_ptr plain) { context->reset_component(plain); });
}

ReturnCode_t PeriodicECSharedComposite::onFinalize()
{
    if (m_org == nullptr)
        return RTC_OK;
    m_org->removeAllMembers();
    // The organization ends here rather than in exit(): the manager may release this component
    // before exit() returns.
    Runtime::releaseServant(m_pPOA, m_org);
    m_org = nullptr;
    return RTC_OK;
}

ReturnCode_t PeriodicECSharedComposite::exit()
{
    return RTObject_impl::exit();
}

SDOPackage::OrganizationList *PeriodicECSharedComposite::get_owned_organizations()
{
    auto *list = new SDOPackage::OrganizationList;
    if (m_org != nullptr) {
        list->length(1);
        (*list)[0] = m_org->getObjRef();
    }
    return list;
}

} // namespace RTC

extern "C" {

void PeriodicECSharedCompositeInit(RTC::Manager *manager)
{
    if (manager == nullptr)
        return;
    coil::Properties profile(compositeSpec);
    manager->registerFactory(profile, RTC::Create<RTC::PeriodicECSharedComposite>,
                             RTC::Delete<RTC::PeriodicECSharedComposite>);
}

}
