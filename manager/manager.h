// SPDX-License-Identifier: MIT
#pragma once

#include "componentfactory.h"
#include "createrequest.h"
#include "forkserver.h"
#include "moduleprofiler.h"
#include "namingregistrar.h"
#include "properties.h"
#include "pythonmoduleloader.h"

#include <Manager.hh>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <sys/types.h>
#include <thread>
#include <vector>

namespace Tls {
struct Settings;
}

namespace Runtime {

class RtObject;

/**
 * An OpenRTM-compatible manager: owns the ORB, creates and deletes components from registered
 * factories (built-ins and loaded modules), registers them and itself in the naming services,
 * serves RTM::Manager at `corbaloc:iiop:<host>:<port>/manager`, and as master spawns and drives
 * slave managers (the same executable in slave mode). Every request that fails records a message
 * naming the problem (lastError(), also in the profile as `last_error`); a refused create_component
 * is also kept by its request text (profile key `rtstudio.create_error.<request>`, the latest
 * maxKeptRefusals), so a client whose creates run side by side reads the reason of its own.
 */
class Manager
{
public:
    /// @p config: OpenRTM's rtc.conf keys (see manager.md) already merged with command-line overrides.
    explicit Manager(const Properties &config);
    ~Manager();
    Manager(const Manager &) = delete;
    Manager &operator=(const Manager &) = delete;

    /// Starts slave processes through a fork server from now on (see ForkServer; the program must
    /// answer `--fork-server`). Call before start(), from the main thread. Without it, or when the
    /// server is gone, each slave is a fork and exec of this program.
    void startForkServer();
    /// Initialises the ORB on the configured endpoint and starts serving; false with @p error on failure.
    bool start(std::string *error);
    /// Serves until shutdown() finishes; after restart() also releases the ORB and its endpoint.
    void run();
    /// Deletes components, unregisters names, leaves the master, stops the ORB. Returns at once.
    void shutdown();

    void registerFactory(ComponentFactory factory);
    /// Creates per `Type?k=v&…` (locally or on a slave); nil and @p error when it fails.
    RTC::RTObject_ptr createComponent(const std::string &request, std::string *error);
    /**
     * createComponent() for each of @p requests in turn, up to the first that fails: the list
     * holds the components made before it, and @p error says why that one failed.
     */
    RTC::RTCList createComponents(const std::vector<std::string> &requests, std::string *error);
    /// How many refused create requests the profile names with their reasons, and the longest
    /// request text kept (a longer one has its reason in `last_error` only).
    static constexpr std::size_t maxKeptRefusals = 64;
    static constexpr std::size_t maxKeptRequestLength = 1024;
    bool deleteComponent(const std::string &instanceName, std::string *error);
    /**
     * Takes over @p servant, created and initialized by its program (OpenRTM's
     * registerComponent): lists it under its instance name and binds its names. False with
     * @p error when the name is empty or taken.
     */
    bool adoptComponent(RtObject *servant, std::string *error);
    /// Unlists @p servant and unbinds its names, leaving the object to its owner (unregisterComponent).
    bool releaseComponent(RtObject *servant);
    /// This process's components.
    RTC::RTCList components();
    /**
     * This process's components named @p name, in OpenRTM-aist's forms: `Instance0` or
     * `category/Instance0`, where the category `*` matches any. A master answers for its own
     * components only, as OpenRTM-aist's does.
     */
    RTC::RTCList componentsByName(const std::string &name);

    /**
     * What the live slaves report (a master's part of get_components() and its relatives): each
     * slave is asked in parallel, bounded by manager.slave_call_timeout (ms, default 2000); a slave
     * that fails or does not answer in time is skipped.
     */
    RTC::RTCList slaveComponents();
    RTC::ComponentProfileList slaveComponentProfiles();

    /**
     * Finalises the components like shutdown(), then lets run() return with restartRequested()
     * set, so that the process runs again with the same command line (and endpoint).
     */
    void restart();
    bool restartRequested() const { return m_restart; }
    /// Starts a new slave manager process registered with the master (this one when it is the
    /// master); false with @p error when it does not start.
    bool forkSlave(std::string *error);
    /**
     * A well-known object of this manager: `NameService` (its first name server), `manager`
     * (itself), `master` (its master; itself for a master). Nil for other names.
     */
    CORBA::Object_ptr service(const std::string &name);

    /**
     * How a loaded module's init function is called: the component SDK installs a call that
     * passes its RTC::Manager, as OpenRTM-aist modules expect. Without one no module loads.
     */
    using ModuleInitCall = std::function<void(void *initFunction)>;

    /**
     * Steps of a local component creation that observers may watch (the SDK's RTM:: action
     * listeners): the request text, the component's properties before and after the
     * configuration files and the request apply, initialisation, and its names when they are
     * bound or unbound. Unset members are skipped. Called without the manager's lock.
     */
    struct LifecycleHooks
    {
        std::function<void(std::string &request)> preCreate;
        std::function<void(RtObject *component)> postCreate;
        std::function<void(Properties &properties)> preConfigure;
        std::function<void(Properties &properties)> postConfigure;
        std::function<void()> preInitialize;
        std::function<void()> postInitialize;
        std::function<void(RtObject *component, std::vector<std::string> &names, bool bind)> preNaming;
        std::function<void(RtObject *component, std::vector<std::string> &names, bool bind)> postNaming;
    };
    void setLifecycleHooks(LifecycleHooks hooks);
    void setModuleInitCall(ModuleInitCall call);
    /**
     * Loads module @p path (found by findModuleFile()) and runs its init function (by default
     * `<Name>Init`): a shared library, or a Python module run by the interpreter this process
     * embeds on first use (PythonModuleLoader). False with @p error when it does not load.
     */
    bool loadModule(const std::string &path, const std::string &initFunction, std::string *error);
    /**
     * loadModule() for a module a request from outside names (load_module, a create that finds its
     * type's module): unless `manager.modules.abs_path_allowed` is YES (OpenRTM-aist's key; ours
     * defaults to NO), the file must lie in one of the module folders — the load path, the package
     * store, the package path — so that a caller cannot make the manager run any library on the
     * machine.
     */
    bool loadRequestedModule(const std::string &path, const std::string &initFunction, std::string *error);
    /// The module file @p name stands for: itself when absolute, else found in the load path (with or
    /// without ".so" or ".py").
    std::string findModuleFile(const std::string &name) const;
    /// The names of the component packages installed: in the package store and below
    /// `manager.modules.package_path`.
    std::vector<std::string> installedPackages() const;
    bool unloadModule(const std::string &path, std::string *error);
    /// Loads `manager.modules.preload` (and the older `manager.preload.modules`): `file[:init],…`.
    void preloadModules();
    /// Creates `manager.components.precreate`: `Type[?k=v&…],…`.
    void precreateComponents();
    /**
     * The component types the modules in `manager.modules.load_path` register (each module loaded
     * by a process of its own, see ModuleProfiler; `manager.modules.profile_timeout` ms per
     * module): a factory profile with `module_file_name` and `module_file_path` per type. Without
     * a profiling program (setModuleProfileProgram()), the `.so` files by name.
     */
    std::vector<Properties> loadableModules();
    /**
     * The module folders of installed component packages (a package store): for @p version empty,
     * every installed version, each package's newest first; else the folders of that version.
     */
    using PackageModuleDirs = std::function<std::vector<std::string>(const std::string &version)>;
    /**
     * Makes the folders @p dirs gives part of the module load path, after
     * `manager.modules.load_path`: their types are loadable at once, and a create request takes
     * the type from the newest installed version, or from the one its `version=` names. Call
     * before start().
     */
    void setPackageModuleDirs(PackageModuleDirs dirs);
    /// The module files the running components of this process were made from (not built-ins).
    std::vector<std::string> runningModulePaths();
    /// Serves @p servant in this manager's POA (which holds a reference to it); nil before start().
    CORBA::Object_ptr activate(PortableServer::ServantBase *servant);
    /// The object RTStudio::Manager::get_package_installer() answers; nil when none is set.
    void setPackageInstaller(CORBA::Object_ptr installer);
    CORBA::Object_ptr packageInstaller();
    /// The program that answers `--module-profile FILE` (rtmanager); call before start().
    void setModuleProfileProgram(const std::string &program);
    std::vector<Properties> loadedModules();
    std::vector<Properties> factoryProfiles();

    bool isMaster() const { return m_isMaster; }
    RTM::ManagerList masters();
    RTM::ManagerList slaves();
    bool addMaster(RTM::Manager_ptr manager);
    bool removeMaster(RTM::Manager_ptr manager);
    bool addSlave(RTM::Manager_ptr manager);
    bool removeSlave(RTM::Manager_ptr manager);

    Properties configuration();
    /**
     * Sets @p key for set_configuration. Keys that decide what code runs, where packages come from,
     * which files are read or written and how the manager is reached are taken from the manager's
     * own configuration only: refused (false, lastError()).
     */
    bool setConfiguration(const std::string &key, const std::string &value);
    /// Configuration plus `instance_name`, `pid`, `address`, `is_master`, `last_error` and the
    /// kept refusals (`rtstudio.create_error.<request>`).
    Properties profile();
    std::string lastError();
    /// Records @p message as the last error (and prints it) and returns false.
    bool fail(const std::string &message, std::string *error);
    /// `host:port` this manager listens on.
    std::string address() const { return m_address; }
    RTM::Manager_ptr reference();

private:
    /// A number from the configuration, within [0, 1e9] (times, pids); a malformed value is
    /// reported and @p fallback used, one out of range is reported and clamped.
    double configNumber(const std::string &key, double fallback) const;
    /// Defaults of `manager.components.max` and `manager.slaves.max`: far above what a robot runs,
    /// low enough that a runaway client is refused before the host's memory or processes run out.
    static constexpr double DefaultComponentLimit = 4096;
    static constexpr double DefaultSlaveLimit = 256;
    /// Default of `corba.max_connections`: TCP connections accepted at once, well below the
    /// usual 1,024 open files of a process.
    static constexpr double DefaultConnectionLimit = 512;
    struct Component;
    struct Slave;
    struct Module;

    // manager.cpp
    bool initOrb(std::string *error);
    /// OpenRTM-aist's corba.ssl.* keys: TLS for every connection when set.
    Tls::Settings tlsSettings() const;
    RTC::RTObject_ptr createRequested(const std::string &request, std::string *error);
    void destroyOrb();
    RTC::RTObject_ptr createLocal(const CreateRequest &request, std::string *error);
    RTC::RTObject_ptr initializeComponent(Component *record, const Properties &properties, std::string *error);
    const ComponentFactory *findFactory(const CreateRequest &request);
    /// The factory of the requested type (a copy), loading `<Type>.so` from the load path if needed.
    std::optional<ComponentFactory> factoryFor(const CreateRequest &request, std::string *why);
    /// The factory of the requested type that @p module registers, loading it if needed.
    std::optional<ComponentFactory> factoryOfModule(const CreateRequest &request, const std::string &module);
    /// The folders of installed packages' modules (see setPackageModuleDirs()).
    std::vector<std::string> installedModuleDirs(const std::string &version) const;
    bool readConfigFiles(Properties *properties, const std::string &instance, const std::string &requestedFile,
                         std::string *error);
    /// Merges the configuration file @p file (none when empty) into @p properties; one that cannot
    /// be read is an error when @p requested, else only reported.
    bool mergeConfigFile(Properties *properties, const std::string &instance, const std::string &file, bool requested,
                         std::string *error);
    /// Holds @p requested (or the first free `<type>N`) for a creation in progress; empty with @p error when taken.
    std::string reserveInstanceName(const std::string &requested, const std::string &typeName, std::string *error);
    void forget(RtObject *component);
    /// A component's exit: forgets it, and shuts down when it was the last one and
    /// manager.shutdown_on_nortcs says so.
    void componentExited(RtObject *component);
    void registerNames(Component &component);
    /**
     * OpenRTM-aist's `naming.update.*`: every `naming.update.interval` seconds (10) asks each name
     * server for one of this manager's names and binds them all again where it is missing (a name
     * server restarted, or reached for the first time); with `naming.update.rebind` every round.
     */
    void keepNamesBound();
    void cleanup();

    // managerslaves.cpp
    RTC::RTObject_ptr createRemote(const CreateRequest &request, std::string *error);
    RTM::Manager_ptr slaveFor(const CreateRequest &request, bool *remoteOnly, std::string *error);
    RTM::Manager_ptr spawnSlave(const std::string &host, int port, const std::string &name, std::string *error);
    /// A free loopback port no other slave being started has; spawnSlave() gives it back.
    int reserveLoopbackPort();
    pid_t startSlaveProcess(const std::string &address, const std::string &name, const std::string &master);
    RTM::Manager_ptr waitForSlave(pid_t pid, const std::string &address);
    /// Asks @p master to take this manager as a slave: empty, or the problem; @p absent when nobody listens there.
    std::string requestJoin(RTM::Manager_ptr master, bool *retry, bool *absent);
    void dropSlave(RTM::Manager_ptr manager);
    void joinMaster();
    void leaveMaster();
    void watchSlaves();
    void watchAsSlave(pid_t parent);
    bool isLocalHost(const std::string &host) const;

    // managermodules.cpp
    /// dlopen()s @p path and calls its @p function through the module init call; its handle in @p handle.
    /// True when @p path's folder is one of the module folders (see loadRequestedModule()).
    bool inModuleFolder(const std::string &path) const;
    bool runSharedModule(const std::string &path, const std::string &function, void **handle, std::string *error);
    /// Runs the Python module @p path and its @p function in the embedded interpreter.
    bool runPythonModule(const std::string &path, const std::string &function, std::string *error);
    /// Forgets the component types module @p modulePath registered. Needs m_mutex held.
    void dropFactoriesOf(const std::string &modulePath);

    Properties m_config;
    bool m_isMaster = false;
    std::string m_address;
    std::string m_instanceName;
    CORBA::ORB_var m_orb;
    PortableServer::POA_var m_poa;
    RTM::Manager_var m_self;
    std::unique_ptr<NamingRegistrar> m_naming;
    std::vector<std::string> m_ownNames;

    std::mutex m_mutex;
    std::condition_variable m_slavesChanged;
    /// One slave start at a time: concurrent creates must not pick one port twice or start one name twice.
    std::mutex m_spawnMutex;
    /// Slaves being started, by the address each is given: from the port's reservation (pid 0, so
    /// that two starts never get one port) until spawnSlave() has them; once launched, their join
    /// needs no call back for their profile.
    struct StartingSlave
    {
        pid_t pid = 0;
        std::string name;
    };
    std::map<std::string, StartingSlave> m_startingSlaves;
    ForkServer m_forkServer;
    std::vector<ComponentFactory> m_factories;
    std::vector<std::unique_ptr<Component>> m_components;
    /// The instance names of m_components and of creations in progress (a lookup per create,
    /// however many components the manager hosts).
    std::set<std::string> m_instanceNames;
    std::vector<std::unique_ptr<Slave>> m_slaves;
    std::vector<std::unique_ptr<Module>> m_modules;
    ModuleInitCall m_moduleInitCall;
    PythonModuleLoader m_pythonModules;
    ModuleProfiler m_moduleProfiler;
    PackageModuleDirs m_packageModuleDirs;
    CORBA::Object_var m_packageInstaller;
    LifecycleHooks m_hooks;
    RTM::ManagerList m_masters;
    std::string m_lastError;
    /// Refused create requests and why, oldest first (at most maxKeptRefusals).
    std::deque<std::pair<std::string, std::string>> m_refusals;
    bool m_stopping = false;
    bool m_restart = false;
    std::thread m_shutdownThread;
    std::thread m_watchdog;
    std::thread m_namingUpdater;
    /// Held by keepNamesBound() while it binds and by forget() while it unbinds.
    std::mutex m_namingMutex;
};

} // namespace Runtime
