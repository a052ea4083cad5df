// SPDX-License-Identifier: MIT
#pragma once

#include <RTStudioManager.hh>

namespace Runtime {

class Manager;

/**
 * RTStudio::Manager servant: the wire face of a Manager (every operation delegates to it). Its
 * references carry RTM::Manager's repository id, as OpenRTM-aist's managers' do; the operations
 * RTStudio::Manager adds are answered all the same to a client that calls them.
 */
class ManagerServant : public virtual POA_RTStudio::Manager
{
public:
    explicit ManagerServant(Runtime::Manager &manager);

    const char *_mostDerivedRepoId() override;

    RTC::ReturnCode_t load_module(const char *pathname, const char *initfunc) override;
    RTC::ReturnCode_t unload_module(const char *pathname) override;
    RTM::ModuleProfileList *get_loadable_modules() override;
    RTM::ModuleProfileList *get_loaded_modules() override;
    RTM::ModuleProfileList *get_factory_profiles() override;
    RTC::RTObject_ptr create_component(const char *module_name) override;
    RTC::RTCList *create_components(const RTStudio::CreateRequestList &requests,
                                    CORBA::String_out error) override;
    RTC::ReturnCode_t delete_component(const char *instance_name) override;
    RTC::RTCList *get_components() override;
    RTC::ComponentProfileList *get_component_profiles() override;
    RTC::RTCList *get_components_by_name(const char *name) override;
    RTM::ManagerProfile *get_profile() override;
    RTM::NVList *get_configuration() override;
    RTC::ReturnCode_t set_configuration(const char *name, const char *value) override;
    CORBA::Boolean is_master() override;
    RTM::ManagerList *get_master_managers() override;
    RTC::ReturnCode_t add_master_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t remove_master_manager(RTM::Manager_ptr mgr) override;
    RTM::ManagerList *get_slave_managers() override;
    RTC::ReturnCode_t add_slave_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t remove_slave_manager(RTM::Manager_ptr mgr) override;
    RTC::ReturnCode_t fork() override;
    RTC::ReturnCode_t shutdown() override;
    RTC::ReturnCode_t restart() override;
    CORBA::Object_ptr get_service(const char *name) override;
    RTStudio::PackageInstaller_ptr get_package_installer() override;

private:
    Runtime::Manager &m_manager;
};

} // namespace Runtime
