// SPDX-License-Identifier: MIT
// A composite component whose members share its periodic execution context, and the SDO
// organization through which it holds them.
#ifndef RTC_PERIODICECSHAREDCOMPOSITE_H
#define RTC_PERIODICECSHAREDCOMPOSITE_H

#include <rtm/PeriodicExecutionContext.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>
#include <rtm/SystemLogger.h>
#include <coil/stringutil.h>

#include <rtmruntime/organization.h>

#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace RTC
{
class Manager;
}

namespace SDOPackage
{
/**
 * The organization a PeriodicECSharedComposite owns. Each member that joins stops its own
 * execution contexts, lists this organization among its organizations, becomes a participant of
 * the composite's first owned context, and has the ports named in the composite's
 * `conf.default.exported_ports` (`<member instance>.<port>`) listed as the composite's ports.
 * A member that leaves is given all of that back and its own contexts are started again.
 */
class PeriodicECOrganization : public ::Runtime::Organization
{
    typedef std::vector<std::string> PortList;

public:
    /// @p rtobj is the composite (which outlives this organization), @p sdo its reference.
    explicit PeriodicECOrganization(::RTC::RTObject_impl *rtobj, SDOSystemElement_ptr sdo);
    ~PeriodicECOrganization() override;

    /// Adds the data-flow components of @p sdo_list (other SDOs are skipped).
    ::CORBA::Boolean add_members(const SDOList &sdo_list) override;
    /// Releases the current members, then makes the data-flow components of @p sdo_list members.
    ::CORBA::Boolean set_members(const SDOList &sdo_list) override;
    /// Releases the member whose instance name is @p id.
    ::CORBA::Boolean remove_member(const char *id) override;
    /// Releases every member (the composite's finalization).
    void removeAllMembers();
    /// Lists and unlists members' ports after `conf.default.exported_ports` changed.
    void updateDelegatedPorts();
    /// This organization's reference.
    Organization_ptr getObjRef();

protected:
    class Member;
    /// Narrows @p sdo to a data-flow component; false when it is none.
    static bool sdoToDFC(SDO_ptr sdo, ::OpenRTM::DataFlowComponent_ptr &dfc);
    static void stopOwnedEC(Member &member);
    static void startOwnedEC(Member &member);
    void addOrganizationToTarget(Member &member);
    void removeOrganizationFromTarget(Member &member);
    /// Makes @p rtobj a participant of the shared context; a nested composite adds its members.
    void addRTCToEC(RTC::RTObject_ptr rtobj);
    void addParticipantToEC(Member &member);
    void removeParticipantFromEC(Member &member);
    /// Lists those of @p member's ports that @p portlist names as the composite's ports.
    void addPort(Member &member, PortList &portlist);
    /// Unlists those of @p member's ports that @p portlist names (and drops them from it).
    void removePort(Member &member, PortList &portlist);
    /// Reads the exported port names from the composite's `conf.default.exported_ports`.
    void updateExportedPortsList();

protected:
    RTC::Logger rtclog;
    ::RTC::RTObject_impl *m_rtobj;
    ::RTC::ExecutionContext_var m_ec;

    /// What the organization keeps of one member: its reference, profile, contexts and configuration.
    class Member
    {
    public:
        explicit Member(RTC::RTObject_ptr rtobj);

        RTC::RTObject_var rtobj_;
        RTC::ComponentProfile_var profile_;
        RTC::ExecutionContextList_var eclist_;
        SDOPackage::Configuration_var config_;
    };

    std::vector<Member> m_rtcMembers;
    typedef std::vector<Member>::iterator MemIt;
    PortList m_expPorts;

private:
    bool isMemberOrOwner(RTC::RTObject_ptr rtobj);
    void publishProperties();

    /// Members change through CORBA calls and configuration listeners on different threads.
    std::recursive_mutex m_memberMutex;
};
} // namespace SDOPackage

namespace RTC
{
/**
 * OpenRTM-aist's composite component `PeriodicECSharedComposite` (category
 * `composite.PeriodicECShared`). Its configuration parameter `members` names the components
 * (instance names in this manager) it runs on its own periodic execution context, in that order,
 * after itself; `exported_ports` names the members' ports (`Motor0.out`) it lists as its own.
 * Activating, deactivating or resetting the composite does the same to its members. A member
 * name this manager does not know makes the composite's initialization fail, naming it.
 */
class PeriodicECSharedComposite : public RTObject_impl
{
public:
    explicit PeriodicECSharedComposite(Manager *manager);
    ~PeriodicECSharedComposite() override;

    /// Initializes as every component, then lets the members join the now existing context.
    ReturnCode_t initialize() override;
    ReturnCode_t onInitialize() override;
    ReturnCode_t onActivated(RTC::UniqueId exec_handle) override;
    void activateChildComp(const RTC::RTObject_ptr rtobj);
    ReturnCode_t onDeactivated(RTC::UniqueId exec_handle) override;
    void deactivateChildComp(const RTC::RTObject_ptr rtobj);
    ReturnCode_t onReset(RTC::UniqueId exec_handle) override;
    void resetChildComp(const RTC::RTObject_ptr rtobj);
    ReturnCode_t onFinalize() override;
    ReturnCode_t exit() override;
    SDOPackage::OrganizationList *get_owned_organizations() override;

protected:
    /// The `members` parameter: member instance names, in execution order.
    std::vector<std::string> m_members;
    OpenRTM::DataFlowComponent_var m_ref;
    SDOPackage::PeriodicECOrganization *m_org;
};
} // namespace RTC

extern "C"
{
/// Registers the PeriodicECSharedComposite factory with @p manager.
void PeriodicECSharedCompositeInit(RTC::Manager *manager);
}

#endif // RTC_PERIODICECSHAREDCOMPOSITE_H
