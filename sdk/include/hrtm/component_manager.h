// SPDX-License-Identifier: MIT
/*!
 * @file component_manager.h
 * @brief hrtm::ComponentManager: the process's RTC::Manager with HRTM's names.
 *
 * @code
 * void ModuleInit(hrtm::ComponentManager* manager) {
 *     hrtm::utils::Properties profile(camera_spec);
 *     manager->regist<Camera>(&profile, 0, 0);
 *     manager->create_component("Camera");
 * }
 * int main(int argc, char** argv) {
 *     hrtm::ComponentManager& manager = hrtm::ComponentManager::instance(argc, argv);
 *     manager.set_init_proc(ModuleInit);
 *     manager.activate();
 *     manager.run();
 * }
 * @endcode
 */
#ifndef HRTM_COMPONENT_MANAGER_H
#define HRTM_COMPONENT_MANAGER_H

#include <rtm/Factory.h>
#include <rtm/Manager.h>

#include <condition_variable>
#include <mutex>

namespace RTC {
class RTObject_impl;
} // namespace RTC

namespace hrtm {
/*! The factory function regist() registers: a new @p T_New. */
template<class T_New> RTC::RTObject_impl *Create(RTC::Manager * /* manager */)
{
    return new T_New();
}

/*! The matching deleter: @p rtc is the @p T_Delete Create made (RTObject_impl is only declared here). */
template<class T_Delete> void Delete(RTC::RTObject_impl *rtc)
{
    delete static_cast<T_Delete *>(rtc);
}

class DataFlowComponent;
class ComponentManager;
/*! A module's initialisation function, called by activate(). */
using ModuleInitProc = void (*)(hrtm::ComponentManager *);

/*!
 * The manager of an HRTM component program. instance(argc, argv) makes it the process's
 * RTC::Manager (from the same command line and rtc.conf), so everything RTC::Manager offers
 * is available on it too.
 */
class ComponentManager : public RTC::Manager
{
public:
    /*! Registers component type @p CompType with @p profile (type_name, conf.*, …). */
    template<typename CompType>
    bool regist(coil::Properties *profile, const char * /*unused*/, const char * /*unused*/)
    {
        return RTC::Manager::registerFactory(*profile, hrtm::Create<CompType>, hrtm::Delete<CompType>);
    }
    /*!
     * Creates a component from `TypeName[?key=value&…]` as RTC::Manager::createComponent();
     * null when that fails or the component is not an hrtm::DataFlowComponent.
     */
    virtual DataFlowComponent *create_component(const char *component_name);
    /*! The function activate() calls (to register and create components). */
    virtual void set_init_proc(void (*init_proc)(hrtm::ComponentManager *));
    /*! RTC::Manager::activateManager(). */
    virtual bool activate();
    /*! RTC::Manager::runManager(). */
    virtual void run(bool non_block = false);
    /*! Calls the set_init_proc() function with the manager (an RTC::ModuleInitProc). */
    static void init_proc(RTC::Manager *mgr);
    /*!
     * The manager, created on the first call from @p argc / @p argv. A process whose
     * RTC::Manager already exists cannot get one (it is logged and the process exits, as for an
     * unusable command line).
     */
    static ComponentManager &instance(int argc, char **argv);

protected:
    ComponentManager();
    virtual ~ComponentManager();

protected:
    static ModuleInitProc initProc;
    static ComponentManager *manager;
    static std::mutex mutex;
};
} // namespace hrtm

#endif // HRTM_COMPONENT_MANAGER_H
