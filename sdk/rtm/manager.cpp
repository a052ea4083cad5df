// SPDX-License-Identifier: MIT
// RTC::Manager: OpenRTM-aist's manager interface on the runtime's Runtime::Manager.
#include <rtm/Manager.h>
#include <rtm/CORBA_RTCUtil.h>
#include <rtm/LocalServiceAdmin.h>
#include <rtm/ManagerServant.h>
#include <rtm/NamingManager.h>
#include <rtm/PeriodicECSharedComposite.h>
#include <rtm/RTObject.h>

#include "loggersink.h"
#include "manageractions.h"
#include "properties.h"
#include "sdkinternal.h"

#include <componentfactory.h>
#include <corbautil.h>
#include <createrequest.h>
#include <executioncontext.h>
#include <executioncontextfactory.h>
#include <manager.h>
#include <managerconfig.h>
#include <returncode.h>

#include <condition_variable>
#include <iterator>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

namespace RTC {

namespace {


/// Signals end the manager cleanly: one thread waits for them (they are blocked everywhere else).
void handleSignalsInOneThread()
{
    static sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    std::thread([] {
        int number = 0;
        sigwait(&signals, &number);
        Manager::terminate();
    }).detach();
}

/// The servant behind @p object when it lives in this process's POA; null otherwise.
RTObject_impl *localServant(PortableServer::POA_ptr poa, CORBA::Object_ptr object)
{
    if (CORBA::is_nil(object))
        return nullptr;
    try {
        PortableServer::ServantBase *servant = poa->reference_to_servant(object);
        auto *component = dynamic_cast<RTObject_impl *>(servant);
        servant->_remove_ref();
        return component;
    } catch (const CORBA::Exception &) {
        return nullptr;
    }
}

/// A failure the caller only sees as a null or false: logged and printed, so that it is never silent.
void reportError(Logger &rtclog, const std::string &message)
{
    RTC_ERROR_STR(message);
    if (!Sdk::LoggerSink::instance().reachesStandardError(Logger::RTL_ERROR))
        std::cerr << message << std::endl;
}

const char *returnCodeName(RTC::ReturnCode_t code)
{
    const char *name = RtStudio::returnCodeName(static_cast<long>(code));
    return name ? name : "an unknown return code";
}

/**
 * A component and one of its ports as rtc.conf's `manager.components.preconnect` and `preactivation`
 * name them: an instance name of this manager (`ConsoleIn0.out`, the port named in full) or a naming
 * address (`rtcname://host/ctx.host_cxt/ConsoleIn0.out`, `rtcloc://…`: the port named by what follows
 * the last slash).
 */
struct PortAddress
{
    std::string component;
    std::string port;
};

PortAddress portAddress(const std::string &text)
{
    const std::size_t dot = text.rfind('.');
    PortAddress address{dot == std::string::npos ? text : text.substr(0, dot), text};
    if (address.component.find("://") != std::string::npos)
        address.port = text.substr(text.rfind('/') + 1);
    return address;
}

/**
 * A preconnect entry in OpenRTM-aist 1.x's form, `Comp0.port^Comp1.port(key=value&…)` (some
 * examples' rtc.conf put `:` between the ports), written in 2.x's: `Comp0.port?port=Comp1.port&key=value&…`.
 * Other text is returned as it is.
 */
std::string currentPreconnectForm(const std::string &entry)
{
    const std::size_t open = entry.find('(');
    if (entry.find('?') != std::string::npos || open == std::string::npos || entry.back() != ')')
        return entry;
    const std::string ports = entry.substr(0, open);
    std::size_t separator = ports.find('^');
    if (separator == std::string::npos && ports.find("://") == std::string::npos)
        separator = ports.find(':');
    if (separator == std::string::npos)
        return entry;
    const std::string parameters = entry.substr(open + 1, entry.size() - open - 2);
    return ports.substr(0, separator) + "?port=" + ports.substr(separator + 1)
        + (parameters.empty() ? std::string() : "&" + parameters);
}

} // namespace

struct Manager::Private
{
    Runtime::Manager *runtime = nullptr;
    std::unique_ptr<Runtime::Manager> owned;
    coil::Properties config;
    ModuleInitProc initProc = nullptr;
    std::map<std::string, std::unique_ptr<Logger>> loggers;
    Sdk::ManagerActions actions;
    std::mutex mutex;
    std::condition_variable stopped;
    bool running = false;
    bool finished = false;
    std::unique_ptr<NamingManager> naming;
    std::unique_ptr<RTM::ManagerServant> servant;
    /// Instance names of components notifyFinalized() reported, for cleanupComponents().
    std::vector<std::string> finalized;
    coil::Timer<coil::PeriodicFunction> scheduler;
    coil::Timer<coil::DelayedFunction> invoker;
    /// Ticks scheduler and invoker every `timer.tick`; started by the first addTask() / invoke().
    std::thread timerThread;
    std::condition_variable timerWake;
    bool timerStopping = false;

    void startTimer(std::chrono::nanoseconds tick)
    {
        // mutex held
        if (timerThread.joinable())
            return;
        timerThread = std::thread([this, tick] {
            std::unique_lock lock(mutex);
            while (!timerStopping) {
                timerWake.wait_for(lock, tick, [this] { return timerStopping; });
                if (timerStopping)
                    break;
                lock.unlock();
                invoker.tick(tick);
                scheduler.tick(tick);
                lock.lock();
            }
        });
    }
    void stopTimer()
    {
        {
            std::lock_guard lock(mutex);
            timerStopping = true;
        }
        timerWake.notify_all();
        if (timerThread.joinable() && timerThread.get_id() != std::this_thread::get_id())
            timerThread.join();
    }
};

Manager::Manager()
    : d(new Private)
{
}

Manager::~Manager()
{
    d->stopTimer();
    delete d;
}

namespace {

std::chrono::nanoseconds timerTick(coil::Properties &config)
{
    double seconds = 0.1;
    try {
        const std::string text = config.getProperty("timer.tick");
        if (!text.empty())
            seconds = std::stod(text);
    } catch (...) {
        // An unreadable tick keeps OpenRTM's default.
    }
    if (!(seconds > 0.0))
        seconds = 0.1;
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Runtime::boundedSeconds(seconds));
}

} // namespace

Manager::TaskId Manager::addTask(std::function<void(void)> fn, std::chrono::nanoseconds period)
{
    TaskId id = d->scheduler.emplace(std::move(fn), period);
    std::lock_guard lock(d->mutex);
    d->startTimer(timerTick(d->config));
    return id;
}

void Manager::invoke(std::function<void(void)> fn, std::chrono::nanoseconds delay)
{
    d->invoker.emplace(std::move(fn), delay);
    std::lock_guard lock(d->mutex);
    d->startTimer(timerTick(d->config));
}

Manager *Manager::manager = nullptr;
std::mutex Manager::mutex;

bool Sdk::adoptManager(Manager *adopted)
{
    std::lock_guard lock(Manager::mutex);
    if (Manager::manager != nullptr)
        return false;
    Manager::manager = adopted;
    return true;
}

Manager *Manager::attach(Runtime::Manager *runtime)
{
    std::lock_guard lock(mutex);
    if (manager == nullptr)
        manager = new Manager;
    Manager *self = manager;
    self->d->runtime = runtime;
    self->d->config = Sdk::toCoil(runtime->configuration());
    Sdk::LoggerSink::instance().configure(runtime->configuration());
    runtime->setModuleInitCall([self](void *function) { reinterpret_cast<ModuleInitProc>(function)(self); });
    self->d->actions.install(*runtime);
    return self;
}

Manager *Manager::init(int argc, char **argv)
{
    Manager *self = nullptr;
    {
        std::lock_guard lock(mutex);
        if (manager != nullptr && manager->d->runtime != nullptr)
            return manager;
        if (manager == nullptr)
            manager = new Manager;
        self = manager;
    }
    self->initManager(argc, argv);
    // OpenRTM-aist's manager offers the composite type in every program, before any module loads.
    PeriodicECSharedCompositeInit(self);
    self->initLocalService();
    return self;
}

void Manager::initManager(int argc, char **argv)
{
    Runtime::Properties config;
    std::string error;
    if (!Runtime::parseManagerArguments(argc, argv, &config, &error)) {
        std::cerr << (argc > 0 ? argv[0] : "manager") << ": " << error << std::endl;
        std::exit(1);
    }
    handleSignalsInOneThread();
    auto runtime = std::make_unique<Runtime::Manager>(config);
    if (!runtime->start(&error)) {
        std::cerr << (argc > 0 ? argv[0] : "manager") << ": " << error << std::endl;
        std::exit(1);
    }
    attach(runtime.get());
    d->owned = std::move(runtime);
}

bool Manager::initLocalService()
{
    RTM::LocalServiceAdmin::instance().init(d->config.getNode("manager.local_service"));
    return true;
}

Manager::InstanceName::InstanceName(RTObject_impl *comp)
    : m_name(comp != nullptr ? comp->getInstanceName() : "")
{
}

Manager::InstanceName::InstanceName(const char *name)
    : m_name(name != nullptr ? name : "")
{
}

Manager::InstanceName::InstanceName(std::string name)
    : m_name(std::move(name))
{
}

bool Manager::InstanceName::operator()(RTObject_impl *comp)
{
    return comp != nullptr && m_name == comp->getInstanceName();
}

Manager &Manager::instance()
{
    {
        std::lock_guard lock(mutex);
        if (manager != nullptr && manager->d->runtime != nullptr)
            return *manager;
    }
    char program[] = "manager";
    char *argv[] = {program, nullptr};
    return *init(1, argv);
}

void Manager::terminate()
{
    Manager *self = nullptr;
    {
        std::lock_guard lock(mutex);
        self = manager;
    }
    if (self != nullptr)
        self->shutdown();
}

void Manager::shutdown()
{
    if (d->runtime == nullptr)
        return;
    d->actions.each(d->actions.manager, [](RTM::ManagerActionListener &l) { l.preShutdown(); });
    d->stopTimer();
    RTM::LocalServiceAdmin::instance().finalize();
    d->runtime->shutdown();
}

void Manager::join()
{
    std::unique_lock lock(d->mutex);
    d->stopped.wait(lock, [this] { return d->finished || !d->running; });
}

coil::Properties &Manager::getConfig()
{
    return d->config;
}

void Manager::setModuleInitProc(ModuleInitProc proc)
{
    d->initProc = proc;
}

bool Manager::activateManager()
{
    if (d->runtime == nullptr)
        return false;
    d->runtime->preloadModules();
    if (d->initProc != nullptr)
        d->initProc(this);
    d->runtime->precreateComponents();
    initPreConnection();
    initPreActivation();
    return true;
}

RTC::RTObject_ptr Manager::findComponent(const std::string &name)
{
    RTC::RTCList list = name.find("://") == std::string::npos ? d->runtime->componentsByName(name)
                                                                : getNaming()->string_to_component(name);
    return list.length() > 0 ? RTC::RTObject::_duplicate(list[0]) : RTC::RTObject::_nil();
}

void Manager::initPreConnection()
{
    forEachStartupEntry("manager.components.preconnect", [this](const std::string &entry, const Failure &fail) {
        // The first port, then those named by `port` and `port<N>`; every other parameter is
        // the connector's (dataport.<key>).
        const std::string request = currentPreconnectForm(entry);
        const PortAddress first = portAddress(request.substr(0, request.find('?')));
        std::vector<PortAddress> others;
        coil::Properties properties;
        for (const auto &[key, value] : coil::urlparam2map(request)) {
            int number = 0;
            if (key == "port"
                || (key.compare(0, 4, "port") == 0 && coil::stringTo(number, key.substr(4).c_str())))
                others.push_back(portAddress(coil::eraseBothEndsBlank(value)));
            else
                properties.setProperty("dataport." + coil::eraseBothEndsBlank(key), coil::eraseBothEndsBlank(value));
        }
        auto portOf = [this, &fail](const PortAddress &address) -> RTC::PortService_ptr {
            RTC::RTObject_var component = findComponent(address.component);
            if (CORBA::is_nil(component)) {
                fail("no component " + address.component);
                return RTC::PortService::_nil();
            }
            RTC::PortService_var port = CORBA_RTCUtil::get_port_by_name(component, address.port);
            if (CORBA::is_nil(port))
                fail(address.component + " has no port " + address.port);
            return port._retn();
        };
        RTC::PortService_var port0 = portOf(first);
        if (CORBA::is_nil(port0))
            return;
        // No second port: the first is connected alone (a port that finds its peer itself).
        if (others.empty())
            others.push_back(PortAddress());
        for (const PortAddress &other : others) {
            RTC::PortService_var port1 = other.component.empty() ? RTC::PortService::_nil() : portOf(other);
            if (!other.component.empty() && CORBA::is_nil(port1))
                continue;
            const RTC::ReturnCode_t result = CORBA_RTCUtil::connect(entry, properties, port0, port1);
            if (result != RTC::RTC_OK)
                fail(std::string("the connection was refused (") + returnCodeName(result) + ")");
        }
    });
}

void Manager::initPreActivation()
{
    forEachStartupEntry("manager.components.preactivation", [this](const std::string &name, const Failure &fail) {
        RTC::RTObject_var component = findComponent(name);
        if (CORBA::is_nil(component)) {
            fail("no such component");
            return;
        }
        const RTC::ReturnCode_t result = CORBA_RTCUtil::activate(component, 0);
        if (result != RTC::RTC_OK)
            fail(std::string("not activated (") + returnCodeName(result) + ")");
    });
}

void Manager::forEachStartupEntry(const std::string &key,
                                  const std::function<void(const std::string &, const Failure &)> &handle)
{
    for (std::string entry : coil::split(d->config.getProperty(key), ",")) {
        entry = coil::eraseBothEndsBlank(entry);
        if (entry.empty())
            continue;
        const Failure fail = [this, &key, &entry](const std::string &why) {
            reportError(getLogbuf(), key + ": " + entry + ": " + why);
        };
        try {
            handle(entry, fail);
        } catch (const CORBA::Exception &e) {
            fail(Runtime::describeException(e));
        }
    }
}

void Manager::runManager(bool no_block)
{
    {
        std::lock_guard lock(d->mutex);
        if (d->running || d->runtime == nullptr)
            return;
        d->running = true;
    }
    auto serve = [this] {
        d->runtime->run();
        d->actions.each(d->actions.manager, [](RTM::ManagerActionListener &l) { l.postShutdown(); });
        std::lock_guard lock(d->mutex);
        d->finished = true;
        d->stopped.notify_all();
    };
    if (no_block)
        std::thread(serve).detach();
    else
        serve();
}

ReturnCode_t Manager::load(const std::string &fname, const std::string &initfunc)
{
    std::string module = fname;
    std::string function = initfunc;
    d->actions.each(d->actions.module, [&](RTM::ModuleActionListener &l) { l.preLoad(module, function); });
    std::string error;
    if (!d->runtime->loadModule(module, function, &error))
        return error.find("no module file") != std::string::npos ? RTC::BAD_PARAMETER : RTC::RTC_ERROR;
    d->actions.each(d->actions.module, [&](RTM::ModuleActionListener &l) { l.postLoad(module, function); });
    return RTC::RTC_OK;
}

ReturnCode_t Manager::load(coil::Properties &prop, const std::string &initfunc)
{
    const std::string path = prop.getProperty("module_file_path", prop.getProperty("module_file_name"));
    return load(path, initfunc);
}

void Manager::unload(const char *fname)
{
    if (fname == nullptr)
        return;
    std::string module = fname;
    d->actions.each(d->actions.module, [&](RTM::ModuleActionListener &l) { l.preUnload(module); });
    if (d->runtime->unloadModule(module, nullptr))
        d->actions.each(d->actions.module, [&](RTM::ModuleActionListener &l) { l.postUnload(module); });
}

void Manager::unloadAll()
{
    for (const Runtime::Properties &module : d->runtime->loadedModules())
        d->runtime->unloadModule(module.value("file_path"), nullptr);
}

namespace {

std::vector<coil::Properties> toCoilList(const std::vector<Runtime::Properties> &list)
{
    std::vector<coil::Properties> result;
    for (const Runtime::Properties &entry : list)
        result.push_back(Sdk::toCoil(entry));
    return result;
}

} // namespace

std::vector<coil::Properties> Manager::getLoadedModules()
{
    return toCoilList(d->runtime->loadedModules());
}

std::vector<coil::Properties> Manager::getLoadableModules()
{
    return toCoilList(d->runtime->loadableModules());
}

bool Manager::registerFactory(coil::Properties &profile, RtcNewFunc new_func, RtcDeleteFunc delete_func)
{
    (void)delete_func; // components go when the ORB drops its last reference (see RTC::Delete)
    if (new_func == nullptr || profile.getProperty("implementation_id").empty())
        return false;
    Runtime::ComponentFactory factory;
    factory.profile = Sdk::toRuntime(profile);
    factory.create = [this, new_func](PortableServer::POA_ptr) -> Runtime::RtObject * { return new_func(this); };
    d->runtime->registerFactory(std::move(factory));
    return true;
}

std::vector<coil::Properties> Manager::getFactoryProfiles()
{
    return toCoilList(d->runtime->factoryProfiles());
}

bool Manager::registerECFactory(const char *name, ECNewFunc new_func, ECDeleteFunc delete_func)
{
    if (name == nullptr || new_func == nullptr)
        return false;
    // Contexts go with the component that owns them (through the POA), so any context the
    // factory is asked to delete is deleted as an ExecutionContextBase.
    (void)delete_func;
    return ExecutionContextFactory::instance().addFactory(
               name, new_func, coil::Destructor<ExecutionContextBase, ExecutionContextBase>)
           == coil::FactoryReturn::OK;
}

std::vector<std::string> Manager::getModulesFactories()
{
    std::vector<std::string> ids;
    for (const Runtime::Properties &profile : d->runtime->factoryProfiles())
        ids.push_back(profile.value("implementation_id"));
    return ids;
}

RTObject_impl *Manager::createComponent(const char *comp_args)
{
    if (comp_args == nullptr)
        return nullptr;
    std::string error;
    RTC::RTObject_var object = d->runtime->createComponent(comp_args, &error);
    PortableServer::POA_var poa = getPOA();
    return localServant(poa, object);
}

void Manager::deleteComponent(RTObject_impl *comp)
{
    if (comp != nullptr)
        deleteComponent(comp->getInstanceName());
}

void Manager::deleteComponent(const char *instance_name)
{
    if (instance_name != nullptr)
        d->runtime->deleteComponent(instance_name, nullptr);
}

RTObject_impl *Manager::getComponent(const char *instance_name)
{
    if (instance_name == nullptr)
        return nullptr;
    PortableServer::POA_var poa = getPOA();
    RTC::RTCList list = d->runtime->componentsByName(instance_name);
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (RTObject_impl *component = localServant(poa, list[i]))
            return component;
    }
    return nullptr;
}

std::vector<RTObject_impl *> Manager::getComponents()
{
    PortableServer::POA_var poa = getPOA();
    std::vector<RTObject_impl *> result;
    RTC::RTCList list = d->runtime->components();
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (RTObject_impl *component = localServant(poa, list[i]))
            result.push_back(component);
    }
    return result;
}

ExecutionContextBase *Manager::createContext(const char *ec_args)
{
    if (ec_args == nullptr || *ec_args == '\0')
        return nullptr;
    std::string error;
    const std::optional<Runtime::CreateRequest> request = Runtime::CreateRequest::parse(ec_args, &error);
    if (!request) {
        reportError(getLogbuf(), "createContext: " + error);
        return nullptr;
    }
    Runtime::Properties properties = d->runtime != nullptr ? d->runtime->configuration() : Runtime::Properties();
    properties.merge(request->properties);
    std::string type = request->implementationId;
    const std::string refusal = Runtime::ExecutionContextFactory::instance().check(type);
    if (!refusal.empty()) {
        reportError(getLogbuf(), "createContext: " + refusal);
        return nullptr;
    }
    ExecutionContextBase *context = ExecutionContextFactory::instance().createObject(type);
    if (context == nullptr) {
        reportError(getLogbuf(), "createContext: execution context type '" + type
                                     + "' is the runtime's own, not an RTC::ExecutionContextBase");
        return nullptr;
    }
    coil::Properties props = Sdk::toCoil(properties);
    context->init(props);
    return context;
}

bool Manager::registerComponent(RTObject_impl *comp)
{
    if (comp == nullptr || d->runtime == nullptr)
        return false;
    std::string error;
    if (!d->runtime->adoptComponent(comp, &error)) {
        reportError(getLogbuf(), "registerComponent: " + error);
        return false;
    }
    return true;
}

bool Manager::unregisterComponent(RTObject_impl *comp)
{
    return comp != nullptr && d->runtime != nullptr && d->runtime->releaseComponent(comp);
}

void Manager::notifyFinalized(RTObject_impl *comp)
{
    if (comp == nullptr)
        return;
    std::lock_guard lock(d->mutex);
    d->finalized.push_back(comp->getInstanceName());
}

void Manager::cleanupComponents()
{
    std::vector<std::string> names;
    {
        std::lock_guard lock(d->mutex);
        names.swap(d->finalized);
    }
    for (const std::string &name : names)
        d->runtime->deleteComponent(name, nullptr);
}

void Manager::cleanupComponent(RTObject_impl *comp)
{
    unregisterComponent(comp);
}

PortableServer::POA_ptr Manager::getShortCutPOA()
{
    return getPOA();
}

RTM::ManagerServant &Manager::getManagerServant()
{
    std::lock_guard lock(d->mutex);
    if (!d->servant)
        d->servant = std::make_unique<RTM::ManagerServant>();
    return *d->servant;
}

NamingManager *Manager::getNaming()
{
    std::lock_guard lock(d->mutex);
    if (!d->naming) {
        d->naming = std::make_unique<NamingManager>(this);
        const std::string servers = d->config.getProperty("corba.nameservers");
        std::stringstream list(servers);
        std::string server;
        while (std::getline(list, server, ',')) {
            server.erase(0, server.find_first_not_of(" \t"));
            server.erase(server.find_last_not_of(" \t") + 1);
            if (!server.empty())
                d->naming->registerNameServer("corba", server.c_str());
        }
    }
    return d->naming.get();
}

CORBA::ORB_ptr Manager::getORB()
{
    return Runtime::theOrb()._retn();
}

PortableServer::POA_ptr Manager::getPOA()
{
    return Sdk::rootPoa();
}

PortableServer::POAManager_ptr Manager::getPOAManager()
{
    PortableServer::POA_var poa = getPOA();
    return poa->the_POAManager();
}

void Manager::addManagerActionListener(RTM::ManagerActionListener *listener, bool autoclean)
{
    d->actions.add(d->actions.manager, listener, autoclean);
}

void Manager::removeManagerActionListener(RTM::ManagerActionListener *listener)
{
    d->actions.remove(d->actions.manager, listener);
}

void Manager::addModuleActionListener(RTM::ModuleActionListener *listener, bool autoclean)
{
    d->actions.add(d->actions.module, listener, autoclean);
}

void Manager::removeModuleActionListener(RTM::ModuleActionListener *listener)
{
    d->actions.remove(d->actions.module, listener);
}

void Manager::addRtcLifecycleActionListener(RTM::RtcLifecycleActionListener *listener, bool autoclean)
{
    d->actions.add(d->actions.lifecycle, listener, autoclean);
}

void Manager::removeRtcLifecycleActionListener(RTM::RtcLifecycleActionListener *listener)
{
    d->actions.remove(d->actions.lifecycle, listener);
}

void Manager::addNamingActionListener(RTM::NamingActionListener *listener, bool autoclean)
{
    d->actions.add(d->actions.naming, listener, autoclean);
}

void Manager::removeNamingActionListener(RTM::NamingActionListener *listener)
{
    d->actions.remove(d->actions.naming, listener);
}

void Manager::addLocalServiceActionListener(RTM::LocalServiceActionListener *listener, bool autoclean)
{
    d->actions.add(d->actions.localService, listener, autoclean);
}

void Manager::removeLocalServiceActionListener(RTM::LocalServiceActionListener *listener)
{
    d->actions.remove(d->actions.localService, listener);
}

Logger &Manager::getLogbuf(const std::string &name)
{
    std::lock_guard lock(d->mutex);
    std::unique_ptr<Logger> &logger = d->loggers[name];
    if (!logger)
        logger = std::make_unique<Logger>(name);
    return *logger;
}

LogStreamBuf &Manager::getLogStreamBuf()
{
    return Sdk::LoggerSink::instance().streams();
}

std::string &Manager::getLogLevel()
{
    return d->config["logger.log_level"];
}

Runtime::Manager *Manager::runtime()
{
    return d->runtime;
}

} // namespace RTC
