// SPDX-License-Identifier: MIT
// The manager's face on the wire (RTM::Manager), as C++ code in the manager's process sees it.
#ifndef RTC_MANAGERSERVANT_H
#define RTC_MANAGERSERVANT_H

#include <mutex>
#include <rtm/idl/ManagerSkel.h>
#include <rtm/Manager.h>
#include <rtm/SystemLogger.h>

#include <condition_variable>
#include <iostream>
#include <string>
#include <vector>

namespace RTM
{
/**
 * The process's RTM::Manager object (served at `corbaloc:iiop:host:port/manager`). The runtime
 * serves it; this class is the handle RTC::Manager::getManagerServant() gives to C++ code: its
 * reference, and the master / slave managers it knows.
 */
class ManagerServant
{
public:
    ManagerServant();
    virtual ~ManagerServant();
    ManagerServant(const ManagerServant &) = delete;
    ManagerServant &operator=(const ManagerServant &) = delete;

    /// The RTM::Manager reference of this process's manager.
    RTM::Manager_ptr getObjRef() const;
    /// True: the runtime serves the manager under the object key `manager` from its start.
    bool createINSManager();
    /// The manager at @p host_port (`host:port`), through its corbaloc; nil when none answers.
    RTM::Manager_ptr findManager(const std::string &host_port);
    /// Whether this process's manager is a master (`manager.is_master`).
    CORBA::Boolean is_master();
    RTM::ManagerList *get_master_managers();
    RTM::ManagerList *get_slave_managers();
    RTC::RTCList *get_components();
    RTC::RTCList *get_components_by_name(const char *name);
};

/**
 * The parts of a component module name `RTC:vendor:category:implementation_id:language:version`
 * (anything after `?` ignored). A name with fewer parts is an implementation id alone, of
 * language C++.
 */
class CompParam
{
public:
    CompParam(std::string module_name);
    ~CompParam();
    static const unsigned int prof_list_size = 6;
    /// The keys of the parts, in order: RTC, vendor, category, implementation_id, language, version.
    static const char *prof_list[prof_list_size];
    std::string vendor();
    std::string category();
    std::string impl_id();
    std::string language();
    std::string version();

private:
    std::string m_type;
    std::string m_vendor;
    std::string m_category;
    std::string m_impl_id;
    std::string m_language;
    std::string m_version;
};
} // namespace RTM

#endif // RTC_MANAGERSERVANT_H
