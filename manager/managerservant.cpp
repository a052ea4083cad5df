// SPDX-License-Identifier: MIT
#include "managerservant.h"

#include "corbautil.h"
#include "manager.h"

namespace Runtime {

namespace {

RTM::ModuleProfileList *toProfiles(const std::vector<Properties> &all)
{
    auto *list = new RTM::ModuleProfileList;
    list->length(CORBA::ULong(all.size()));
    for (CORBA::ULong i = 0; i < list->length(); ++i)
        (*list)[i].properties = propertiesToNv(all[i]);
    return list;
}

RTC::ReturnCode_t code(bool ok)
{
    return ok ? RTC::RTC_OK : RTC::BAD_PARAMETER;
}

} // namespace

ManagerServant::ManagerServant(Runtime::Manager &manager)
    : m_manager(manager)
{
}

const char *ManagerServant::_mostDerivedRepoId()
{
    return RTM::Manager::_PD_repoId;
}

RTC::ReturnCode_t ManagerServant::load_module(const char *pathname, const char *initfunc)
{
    return code(m_manager.loadRequestedModule(pathname ? pathname : "", initfunc ? initfunc : "", nullptr));
}

RTC::ReturnCode_t ManagerServant::unload_module(const char *pathname)
{
    return code(m_manager.unloadModule(pathname ? pathname : "", nullptr));
}

RTM::ModuleProfileList *ManagerServant::get_loadable_modules()
{
    return toProfiles(m_manager.loadableModules());
}

RTM::ModuleProfileList *ManagerServant::get_loaded_modules()
{
    return toProfiles(m_manager.loadedModules());
}

RTM::ModuleProfileList *ManagerServant::get_factory_profiles()
{
    return toProfiles(m_manager.factoryProfiles());
}

RTC::RTObject_ptr ManagerServant::create_component(const char *module_name)
{
    return m_manager.createComponent(module_name ? module_name : "", nullptr);
}

RTC::RTCList *ManagerServant::create_components(const RTStudio::CreateRequestList &requests,
                                                CORBA::String_out error)
{
    std::vector<std::string> texts;
    texts.reserve(requests.length());
    for (CORBA::ULong i = 0; i < requests.length(); ++i)
        texts.emplace_back(requests[i].in());
    std::string reason;
    auto *created = new RTC::RTCList(m_manager.createComponents(texts, &reason));
    error = CORBA::string_dup(reason.c_str());
    return created;
}

RTC::ReturnCode_t ManagerServant::delete_component(const char *instance_name)
{
    return code(m_manager.deleteComponent(instance_name ? instance_name : "", nullptr));
}

// A master answers for its slaves too, as OpenRTM-aist's ManagerServant does.
RTC::RTCList *ManagerServant::get_components()
{
    auto *list = new RTC::RTCList(m_manager.components());
    if (m_manager.isMaster())
        appendSequence(*list, m_manager.slaveComponents());
    return list;
}

RTC::ComponentProfileList *ManagerServant::get_component_profiles()
{
    RTC::RTCList all = m_manager.components();
    auto *list = new RTC::ComponentProfileList;
    for (CORBA::ULong i = 0; i < all.length(); ++i) {
        try {
            RTC::ComponentProfile_var profile = all[i]->get_component_profile();
            const CORBA::ULong n = list->length();
            list->length(n + 1);
            (*list)[n] = profile.in();
        } catch (const CORBA::Exception &) {
            // A component going away while we list is left out.
        }
    }
    if (m_manager.isMaster())
        appendSequence(*list, m_manager.slaveComponentProfiles());
    return list;
}

RTC::RTCList *ManagerServant::get_components_by_name(const char *name)
{
    const std::string wanted = name ? name : "";
    return new RTC::RTCList(m_manager.componentsByName(wanted));
}

RTM::ManagerProfile *ManagerServant::get_profile()
{
    auto *profile = new RTM::ManagerProfile;
    profile->properties = propertiesToNv(m_manager.profile());
    return profile;
}

RTM::NVList *ManagerServant::get_configuration()
{
    return new RTM::NVList(propertiesToNv(m_manager.configuration()));
}

RTC::ReturnCode_t ManagerServant::set_configuration(const char *name, const char *value)
{
    return code(m_manager.setConfiguration(name ? name : "", value ? value : ""));
}

CORBA::Boolean ManagerServant::is_master()
{
    return m_manager.isMaster();
}

RTM::ManagerList *ManagerServant::get_master_managers()
{
    return new RTM::ManagerList(m_manager.masters());
}

RTC::ReturnCode_t ManagerServant::add_master_manager(RTM::Manager_ptr mgr)
{
    return code(m_manager.addMaster(mgr));
}

RTC::ReturnCode_t ManagerServant::remove_master_manager(RTM::Manager_ptr mgr)
{
    return code(m_manager.removeMaster(mgr));
}

RTM::ManagerList *ManagerServant::get_slave_managers()
{
    return new RTM::ManagerList(m_manager.slaves());
}

RTC::ReturnCode_t ManagerServant::add_slave_manager(RTM::Manager_ptr mgr)
{
    return code(m_manager.addSlave(mgr));
}

RTC::ReturnCode_t ManagerServant::remove_slave_manager(RTM::Manager_ptr mgr)
{
    return code(m_manager.removeSlave(mgr));
}

RTC::ReturnCode_t ManagerServant::fork()
{
    return code(m_manager.forkSlave(nullptr));
}

RTC::ReturnCode_t ManagerServant::shutdown()
{
    m_manager.shutdown();
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ManagerServant::restart()
{
    // Replies first: the components are finalised and the process runs again after this returns.
    m_manager.restart();
    return RTC::RTC_OK;
}

CORBA::Object_ptr ManagerServant::get_service(const char *name)
{
    return m_manager.service(name ? name : "");
}

RTStudio::PackageInstaller_ptr ManagerServant::get_package_installer()
{
    CORBA::Object_var installer = m_manager.packageInstaller();
    return RTStudio::PackageInstaller::_unchecked_narrow(installer);
}

} // namespace Runtime
