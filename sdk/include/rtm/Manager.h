// SPDX-License-Identifier: MIT
// The manager of a component process: configuration, ORB, naming, modules and components.
#ifndef RTM_MANAGER_H
#define RTM_MANAGER_H

#include <rtm/RTC.h>

#include <rtm/Factory.h>
#include <rtm/ECFactory.h>
#include <rtm/ObjectManager.h>
#include <rtm/SystemLogger.h>
#include <rtm/ManagerActionListener.h>

#include <coil/Properties.h>
#include <coil/Timer.h>
#include <coil/Signal.h>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <list>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace Runtime
{
class Manager;
}

namespace RTM
{
class ManagerServant;
}

namespace RTC
{
class Manager;
class NamingManager;
namespace Sdk
{
bool adoptManager(Manager *manager);
}
using ModuleInitProc = void (*)(Manager *manager);

/**
 * The one manager of a process. A component program calls init(argc, argv) (OpenRTM-aist's
 * command line and rtc.conf), setModuleInitProc(), activateManager() and runManager(); inside
 * rtmanager the manager already exists and modules get it in their init function.
 */
class Manager
{
public:
    Manager(const Manager &) = delete;
    Manager &operator=(const Manager &) = delete;

    /**
     * Creates the manager from the command line (`-f FILE`, `-i`, `-o key:value`, `-p PORT`,
     * `-d`, `-a`; rtc.conf searched as OpenRTM-aist does) and starts the ORB. A second call
     * returns the same manager. On a command line or configuration it cannot use, prints why and
     * exits the process with status 1, as OpenRTM-aist does.
     */
    static Manager *init(int argc, char **argv);
    /// The manager (created with default settings if init() was not called).
    static Manager &instance();
    /// Makes @p manager the process's manager (rtmanager does this for its runtime).
    static Manager *attach(::Runtime::Manager *manager);
    /// Shuts the manager down (from any thread).
    static void terminate();
    /// Same as terminate(): components finalize, names are unbound, the ORB stops.
    void shutdown();
    /// Waits until the manager has shut down.
    void join();

    coil::Properties &getConfig();
    void setModuleInitProc(ModuleInitProc proc);
    /**
     * Serves the manager, loads `manager.modules.preload`, runs the init procedure, creates
     * `manager.components.precreate`, connects `manager.components.preconnect` and activates
     * `manager.components.preactivation`. False when the ORB cannot serve.
     */
    bool activateManager();
    /// Runs until shutdown; with @p no_block true returns at once and runs in the background.
    void runManager(bool no_block = false);

    using TaskId = coil::Timer<coil::PeriodicFunction>::TaskId;
    /**
     * Calls @p fn every @p period from the manager's timer thread (its resolution is
     * `timer.tick` seconds, 0.1 by default) until removeTask().
     */
    TaskId addTask(std::function<void(void)> fn, std::chrono::nanoseconds period);
    /// Stops the task @p id; it is not called again.
    static void removeTask(TaskId id) { id->stop(); }
    /// Calls @p fn once from the manager's timer thread, after @p delay.
    void invoke(std::function<void(void)> fn, std::chrono::nanoseconds delay = std::chrono::seconds::zero());

    /// Loads module @p fname (searched in `manager.modules.load_path`) and calls @p initfunc
    /// (default `<file stem>Init`).
    ReturnCode_t load(const std::string &fname, const std::string &initfunc);
    ReturnCode_t load(coil::Properties &prop, const std::string &initfunc);
    void unload(const char *fname);
    void unloadAll();
    std::vector<coil::Properties> getLoadedModules();
    std::vector<coil::Properties> getLoadableModules();

    /// Registers a component type: @p profile has `implementation_id`, `type_name`, …, `conf.*`.
    bool registerFactory(coil::Properties &profile, RtcNewFunc new_func, RtcDeleteFunc delete_func);
    std::vector<coil::Properties> getFactoryProfiles();
    /**
     * Registers execution context type @p name (what `exec_cxt.periodic.type` names); false when
     * the type is known already. The contexts @p new_func makes must derive from one of the
     * built-in ones (their engine runs them).
     */
    bool registerECFactory(const char *name, ECNewFunc new_func, ECDeleteFunc delete_func);
    std::vector<std::string> getModulesFactories();

    /**
     * Creates a component from `TypeName[?key=value&…]` (instance_name, exec_cxt.periodic.rate,
     * conf.default.x, …), initializes it and registers its names. Null when it fails.
     */
    RTObject_impl *createComponent(const char *comp_args);
    void deleteComponent(RTObject_impl *comp);
    void deleteComponent(const char *instance_name);
    RTObject_impl *getComponent(const char *instance_name);
    std::vector<RTObject_impl *> getComponents();
    /// A new (not started) execution context from `Type[?key=value&…]` (exec_cxt.periodic.rate, …); null
    /// and a message naming the known types when the type is unknown.
    ExecutionContextBase *createContext(const char *ec_args);
    /// Lists @p comp (created and initialized by the program) with the manager and binds its
    /// names, as components the manager creates; false when its instance name is taken.
    bool registerComponent(RTObject_impl *comp);
    /// Unlists @p comp and unbinds its names; the object stays its caller's.
    bool unregisterComponent(RTObject_impl *comp);
    /// Notes that @p comp was finalized: cleanupComponents() deletes it.
    void notifyFinalized(RTObject_impl *comp);
    /// Deletes the components notifyFinalized() named.
    void cleanupComponents();
    /// Unlists and unbinds @p comp at once.
    void cleanupComponent(RTObject_impl *comp);

    CORBA::ORB_ptr getORB();
    CORBA::ORB_ptr theORB() { return getORB(); }
    PortableServer::POA_ptr getPOA();
    PortableServer::POA_ptr thePOA() { return getPOA(); }
    PortableServer::POAManager_ptr getPOAManager();
    PortableServer::POAManager_ptr thePOAManager() { return getPOAManager(); }
    /// The POA of same-process shortcut calls: the root POA here (omniORB calls a servant in
    /// the same process directly already).
    PortableServer::POA_ptr theShortCutPOA() { return getShortCutPOA(); }
    PortableServer::POA_ptr getShortCutPOA();
    /// The manager's RTM::Manager object.
    RTM::ManagerServant &getManagerServant();
    /// The name services components are bound in (`corba.nameservers`).
    NamingManager *getNaming();

    /// Listeners of the manager's actions; with @p autoclean the manager deletes them when removed.
    void addManagerActionListener(RTM::ManagerActionListener *listener, bool autoclean = true);
    void removeManagerActionListener(RTM::ManagerActionListener *listener);
    void addModuleActionListener(RTM::ModuleActionListener *listener, bool autoclean = true);
    void removeModuleActionListener(RTM::ModuleActionListener *listener);
    void addRtcLifecycleActionListener(RTM::RtcLifecycleActionListener *listener, bool autoclean = true);
    void removeRtcLifecycleActionListener(RTM::RtcLifecycleActionListener *listener);
    void addNamingActionListener(RTM::NamingActionListener *listener, bool autoclean = true);
    void removeNamingActionListener(RTM::NamingActionListener *listener);
    void addLocalServiceActionListener(RTM::LocalServiceActionListener *listener, bool autoclean = true);
    void removeLocalServiceActionListener(RTM::LocalServiceActionListener *listener);

    /// Every line the loggers write also goes to this buffer and the streams added to it
    /// (addStream(), e.g. a LogstreamFile's buffer).
    LogStreamBuf &getLogStreamBuf();
    /// A logger named @p name with the manager's logging settings.
    Logger &getLogbuf(const std::string &name = "manager");
    std::string &getLogLevel();

    /// The runtime manager underneath (for RT Studio's own tools).
    ::Runtime::Manager *runtime();

protected:
    // Protected for hrtm::ComponentManager, which becomes the process's manager in its place.
    Manager();
    ~Manager();

    /**
     * What init() does once the manager object exists: reads the command line and the
     * configuration, starts the runtime (ORB, naming) and attaches this manager to it. On a
     * command line or configuration it cannot use, prints why and exits with status 1.
     */
    void initManager(int argc, char **argv);
    /// Starts the local services `manager.local_service.enabled_services` names (RTM::LocalServiceAdmin).
    bool initLocalService();
    /**
     * Connects the ports `manager.components.preconnect` names: entries separated by commas, each
     * `Comp0.port?port=Comp1.port&port1=…&key=value…` (the connector is named by the whole entry, its
     * other parameters are its `dataport.` properties) or OpenRTM-aist 1.x's `Comp0.port^Comp1.port(key=value&…)`.
     * A connection that cannot be made is reported and the next one tried.
     */
    void initPreConnection();
    /// Activates the components `manager.components.preactivation` names (in their first context).
    void initPreActivation();

    /// Matches components by instance name (for ComponentManager).
    struct InstanceName
    {
        explicit InstanceName(RTObject_impl *comp);
        explicit InstanceName(const char *name);
        explicit InstanceName(std::string name);
        bool operator()(RTObject_impl *comp);
        std::string m_name;
    };
    /// Components by instance name.
    using ComponentManager = ObjectManager<std::string, RTObject_impl, InstanceName>;

    /// The process's manager (null before init()) and the lock of its creation.
    static Manager *manager;
    static std::mutex mutex;

private:
    friend bool Sdk::adoptManager(Manager *manager);
    /// A component by instance name or naming address (`rtcname://…`, `rtcloc://…`); nil when none.
    RTC::RTObject_ptr findComponent(const std::string &name);
    /// Reports why an entry of a startup key failed.
    using Failure = std::function<void(const std::string &why)>;
    /// Calls @p handle for each entry of the comma-separated @p key (`manager.components.preconnect`, …)
    /// with the means to report its failure; a CORBA exception it throws is reported too.
    void forEachStartupEntry(const std::string &key,
                             const std::function<void(const std::string &entry, const Failure &fail)> &handle);

    struct Private;
    Private *d;
};
} // namespace RTC

#endif // RTM_MANAGER_H
