// SPDX-License-Identifier: MIT
#include "manager.h"

#include "connectionlimit.h"
#include "corbautil.h"
#include "executioncontextfactory.h"
#include "hostfacts.h"
#include "managerdetail.h"
#include "managerservant.h"
#include "referenceguard.h"
#include "tlstransport.h"

#include <omniORB4/omniORB.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <string_view>
#include <iostream>
#include <unistd.h>

namespace Runtime {

Manager::Manager(const Properties &config)
    : m_config(config)
{
    m_isMaster = m_config.isYes("manager.is_master");
    m_instanceName = expandedInstanceName(m_config.value("manager.instance_name", "manager"), getpid());
    m_config.set("manager.instance_name", m_instanceName);
}

std::string expandedInstanceName(std::string format, pid_t pid)
{
    const size_t at = format.find("%p");
    if (at != std::string::npos)
        format.replace(at, 2, std::to_string(pid));
    return format;
}

Manager::~Manager()
{
    destroyOrb();
}

void Manager::destroyOrb()
{
    if (m_shutdownThread.joinable())
        m_shutdownThread.join();
    if (m_watchdog.joinable())
        m_watchdog.join();
    if (m_namingUpdater.joinable())
        m_namingUpdater.join();
    if (!CORBA::is_nil(m_orb)) {
        try {
            m_orb->destroy();
        } catch (const CORBA::Exception &) {
        }
        m_orb = CORBA::ORB::_nil();
    }
}

Tls::Settings Manager::tlsSettings() const
{
    return {m_config.value("corba.ssl.certificate_authority_file"), m_config.value("corba.ssl.key_file"),
            m_config.value("corba.ssl.key_file_password")};
}

bool Manager::initOrb(std::string *error)
{
    // Where to listen: every entry of corba.endpoints ("all" or a blank host: every interface; no
    // port: one of our choosing, so that the manager knows its own address). A master whose
    // endpoints name no port listens first on the port of corba.master_manager, as OpenRTM-aist does.
    std::vector<std::pair<std::string, int>> endpoints;
    for (std::string entry : split(m_config.value("corba.endpoints"), ',')) {
        entry = trimmed(entry);
        if (entry == "all")
            entry = ":";
        const size_t colon = entry.rfind(':');
        std::string host = colon == std::string::npos ? entry : entry.substr(0, colon);
        const std::string portText = colon == std::string::npos ? std::string() : entry.substr(colon + 1);
        int port = 0;
        std::string ignored;
        if (!portText.empty() && !parseHostPort("h:" + portText, &ignored, &port, error))
            return false;
        endpoints.emplace_back(host == "localhost" ? std::string("127.0.0.1") : host, port);
    }
    const bool anyPort = std::any_of(endpoints.begin(), endpoints.end(), [](const auto &e) { return e.second != 0; });
    if (m_isMaster && !anyPort) {
        std::string masterHost;
        int masterPort = 0;
        if (!parseHostPort(m_config.value("corba.master_manager", "localhost:2810"), &masterHost, &masterPort, error))
            return false;
        endpoints.insert(endpoints.begin(), {std::string(), masterPort});
    }
    if (endpoints.empty())
        endpoints.emplace_back(std::string(), 0);
    std::vector<std::string> args = {"rtmanager"};
    std::string listening;
    const Tls::Settings tls = tlsSettings();
    if (tls.enabled() && !Tls::Transport::install(tls, error))
        return false;
    std::vector<std::string> addresses;
    for (auto &[host, port] : endpoints) {
        if (port == 0)
            port = freeLoopbackPort();
        addresses.push_back(host + ':' + std::to_string(port));
        const std::string giop = (tls.enabled() ? "giop:ssl:" : "giop:tcp:") + addresses.back();
        listening += (listening.empty() ? "" : ", ") + giop;
    }
    if (tls.enabled()) {
        const std::vector<std::string> tlsArgs = Tls::orbArguments(addresses);
        args.insert(args.end(), tlsArgs.begin(), tlsArgs.end());
    } else {
        for (const std::string &address : addresses)
            args.insert(args.end(), {"-ORBendPoint", "giop:tcp:" + address});
    }
    // Peers on the same host (omniORB prefers a Unix socket over TCP when an object's reference
    // offers one) reach this process without the TCP stack: a few microseconds per call instead of
    // tens. Remote peers ignore the socket and use TCP as before. Not with TLS: a socket would let
    // local peers in without a certificate.
    if (!tls.enabled() && m_config.isYes("corba.unix_socket", true)) {
        // A slave's master cleared the folder when it started: slaves started side by side need
        // not each read it again.
        const std::string folder = localSocketFolder(!m_config.contains("manager.spawned_by"));
        if (!folder.empty())
            args.insert(args.end(), {"-ORBunixTransportDirectory", folder, "-ORBendPoint", "giop:unix:"});
    }
    const std::string host = endpoints.front().first;
    const int port = endpoints.front().second;
    // A manager's replies about a large system (profiles of every component) pass omniORB's 2 MiB
    // default; corba.args below may set another limit.
    args.insert(args.end(), {"-ORBgiopMaxMsgSize", "268435456"});
    // No LocateRequest before the first call on each new reference (naming contexts, slaves, the
    // master, peers' ports): one round trip less each; a gone object still fails that first call.
    args.insert(args.end(), {"-ORBverifyObjectExistsAndType", "0"});
    // Bytes after a request's arguments are ignored instead of closing the connection: omniORB 4.2
    // leaks the request's state and buffer (about 8 KiB) with each connection it closes for them, so
    // a peer repeating such requests would grow the manager's memory without bound (fuzz_giop).
    args.insert(args.end(), {"-ORBstrictIIOP", "0"});
    // OpenRTM's corba.args: extra ORB options such as `-ORBgiopMaxMsgSize 209715200`.
    // Quoted as OpenRTM-aist's do: `-ORBserverTransportRule "* ssl"` is one option and its value.
    for (const std::string &word : splitArguments(m_config.value("corba.args"))) {
        if (!word.empty())
            args.push_back(word);
    }
    std::vector<char *> argv;
    for (std::string &arg : args)
        argv.push_back(arg.data());
    int argc = int(argv.size());
    try {
        m_orb = CORBA::ORB_init(argc, argv.data());
        CORBA::Object_var object = m_orb->resolve_initial_references("RootPOA");
        m_poa = PortableServer::POA::_narrow(object);
    } catch (const CORBA::Exception &e) {
        *error = "cannot start the ORB on " + listening + ": " + describeException(e);
        return false;
    }
    std::vector<int> ports;
    for (const auto &endpoint : endpoints)
        ports.push_back(endpoint.second);
    ConnectionLimit::install(int(configNumber("corba.max_connections", DefaultConnectionLimit)), ports);
    Corba::ReferenceGuard::install();
    // No remote call may block forever: every outgoing call and connect is bounded.
    omniORB::setClientCallTimeout(CORBA::ULong(configNumber("corba.call_timeout", 5000)));
    omniORB::setClientConnectTimeout(CORBA::ULong(configNumber("corba.connect_timeout", 2000)));
    m_address = (host.empty() || host == "0.0.0.0" ? std::string("127.0.0.1") : host) + ':' + std::to_string(port);
    return true;
}

bool Manager::start(std::string *error)
{
    // OpenRTM's `-a` (manager.corba_servant: NO): components only, no RTM::Manager object.
    const bool serving = m_config.isYes("manager.corba_servant", true);
    try {
        if (!initOrb(error))
            return false;
        PortableServer::POAManager_var pm = m_poa->the_POAManager();
        pm->activate();
        if (serving) {
            // The POA holds the servant while it is active; destroying the ORB releases the last reference.
            PortableServer::ServantBase_var servant = new ManagerServant(*this);
            CORBA::Object_var object = m_orb->resolve_initial_references("omniINSPOA");
            PortableServer::POA_var ins = PortableServer::POA::_narrow(object);
            PortableServer::ObjectId_var id = PortableServer::string_to_ObjectId("manager");
            ins->activate_object_with_id(id, servant);
            CORBA::Object_var ref = ins->id_to_reference(id);
            m_self = RTM::Manager::_narrow(ref);
            PortableServer::POAManager_var insManager = ins->the_POAManager();
            insManager->activate();
        }
    } catch (const CORBA::Exception &e) {
        *error = "cannot serve the manager on " + m_address + ": " + describeException(e);
        return false;
    }
    m_naming = std::make_unique<NamingRegistrar>(
        m_config.isYes("naming.enable", true) ? split(m_config.value("corba.nameservers", "localhost"), ',')
                                               : std::vector<std::string>());
    Properties values = m_config;
    values.set("instance_name", m_instanceName);
    values.set("manager_name", m_config.value("manager.name", "manager"));
    std::vector<std::string> errors;
    if (!serving)
        return true;
    // A slave its master started stays out of the name servers, as OpenRTM-aist's do: it is reached
    // through its master (get_slave_managers, rtshell's `manager.mgr/slave.mgr`). A manager a user
    // started puts itself there, master or not.
    const std::vector<std::string> names
        = m_config.contains("manager.spawned_by")
              ? std::vector<std::string>()
              : NamingRegistrar::expand(m_config.value("manager.naming_formats", "%h.host_cxt/%n.mgr"), values);
    // Kept also when a server did not take them: keepNamesBound() binds them once it answers.
    for (const std::string &path : names) {
        m_naming->bind(path, m_self, &errors);
        m_ownNames.push_back(path);
    }
    for (const std::string &message : errors)
        std::cerr << programName() << ": " << message << std::endl;
    if (!m_naming->servers().empty() && m_config.isYes("naming.update.enable", true))
        m_namingUpdater = std::thread([this] { keepNamesBound(); });
    if (m_isMaster) {
        m_watchdog = std::thread([this] { watchSlaves(); });
    } else {
        joinMaster();
        const pid_t parent = pid_t(configNumber("manager.spawned_by", 0));
        if (parent > 0 || m_config.isYes("manager.shutdown_auto"))
            m_watchdog = std::thread([this, parent] { watchAsSlave(parent); });
    }
    return true;
}

void Manager::run()
{
    try {
        m_orb->run();
    } catch (const CORBA::BAD_INV_ORDER &) {
        // A shutdown request came in before run() was reached: the ORB is down already.
    }
    // The ORB stops before the thread that stopped it has ended; whoever waits for run() to return
    // (a Python program about to end its interpreter) must find the components' finalization over.
    std::thread stopper;
    {
        std::lock_guard lock(m_mutex);
        stopper.swap(m_shutdownThread);
    }
    if (stopper.joinable())
        stopper.join();
    // The new run of the process must find the endpoint free.
    if (m_restart)
        destroyOrb();
}

void Manager::shutdown()
{
    std::lock_guard lock(m_mutex);
    if (m_stopping)
        return;
    m_stopping = true;
    m_slavesChanged.notify_all();
    // orb->shutdown(true) may not run in an ORB thread, and the caller may be one.
    m_shutdownThread = std::thread([this] {
        cleanup();
        try {
            m_orb->shutdown(true);
        } catch (const CORBA::Exception &) {
            // Already shut down.
        }
    });
}

void Manager::cleanup()
{
    std::vector<std::unique_ptr<Component>> components;
    {
        std::lock_guard lock(m_mutex);
        components.swap(m_components);
        m_instanceNames.clear();
    }
    std::unique_lock naming(m_namingMutex);
    for (auto &component : components) {
        component->servant->setExitHandler({});
        component->servant->shutdownComponent();
        for (const std::string &path : component->names)
            m_naming->unbind(path);
        releaseServant(m_poa, component->servant);
    }
    for (const std::string &path : m_ownNames)
        m_naming->unbind(path);
    naming.unlock();
    if (m_isMaster) {
        RTM::ManagerList all = slaves();
        for (CORBA::ULong i = 0; i < all.length(); ++i) {
            try {
                all[i]->shutdown();
            } catch (const CORBA::Exception &) {
                // A slave that is already gone needs no shutdown.
            }
        }
    } else {
        leaveMaster();
    }
}

void Manager::registerFactory(ComponentFactory factory)
{
    std::lock_guard lock(m_mutex);
    const std::string id = factory.implementationId();
    if (factory.modulePath.empty())
        factory.modulePath = moduleBeingLoaded();
    // A type registered again replaces its factory, unless two module files register it: two
    // installed versions of one package are used side by side.
    m_factories.erase(std::remove_if(m_factories.begin(), m_factories.end(),
                                     [&factory, &id](const ComponentFactory &f) {
                                         return f.implementationId() == id
                                             && (f.modulePath.empty() || factory.modulePath.empty()
                                                 || f.modulePath == factory.modulePath);
                                     }),
                      m_factories.end());
    m_factories.push_back(std::move(factory));
}

bool Manager::fail(const std::string &message, std::string *error)
{
    {
        std::lock_guard lock(m_mutex);
        m_lastError = message;
    }
    std::cerr << programName() << ": " << message << std::endl;
    if (error)
        *error = message;
    return false;
}

std::string Manager::lastError()
{
    std::lock_guard lock(m_mutex);
    return m_lastError;
}

void Manager::setLifecycleHooks(LifecycleHooks hooks)
{
    m_hooks = std::move(hooks);
}

RTC::RTObject_ptr Manager::createComponent(const std::string &requestText, std::string *error)
{
    std::string reason;
    RTC::RTObject_ptr created = createRequested(requestText, &reason);
    if (CORBA::is_nil(created) && requestText.size() <= maxKeptRequestLength) {
        std::lock_guard lock(m_mutex);
        m_refusals.emplace_back(requestText, reason);
        if (m_refusals.size() > maxKeptRefusals)
            m_refusals.pop_front();
    }
    if (error)
        *error = reason;
    return created;
}

RTC::RTCList Manager::createComponents(const std::vector<std::string> &requests, std::string *error)
{
    RTC::RTCList created;
    for (const std::string &request : requests) {
        RTC::RTObject_var component = createComponent(request, error);
        if (CORBA::is_nil(component))
            break;
        const CORBA::ULong n = created.length();
        created.length(n + 1);
        created[n] = component._retn();
    }
    return created;
}

RTC::RTObject_ptr Manager::createRequested(const std::string &requestText, std::string *error)
{
    std::string text = requestText;
    if (m_hooks.preCreate)
        m_hooks.preCreate(text);
    std::string message;
    const std::optional<CreateRequest> request = CreateRequest::parse(text, &message);
    if (!request) {
        fail("create_component: " + message, error);
        return RTC::RTObject::_nil();
    }
    if (request->managerAddress || request->managerName)
        return createRemote(*request, error);
    return createLocal(*request, error);
}

namespace {

/// Whether a factory's @p profile is of the type @p request names (a full `RTC:` id also by its
/// vendor, category, version and language).
bool isRequestedType(const Properties &p, const CreateRequest &request)
{
    return p.value("implementation_id") == request.implementationId
        && (request.vendor.empty() || p.value("vendor") == request.vendor)
        && (request.category.empty() || p.value("category") == request.category)
        && (request.version.empty() || p.value("version") == request.version)
        && (request.language.empty() || p.value("language") == request.language);
}

} // namespace

// The latest registered first: a module loaded later takes over a type.
const ComponentFactory *Manager::findFactory(const CreateRequest &request)
{
    for (auto it = m_factories.rbegin(); it != m_factories.rend(); ++it) {
        if (isRequestedType(it->profile, request))
            return &*it;
    }
    return nullptr;
}

std::string Manager::reserveInstanceName(const std::string &requested, const std::string &typeName,
                                         std::string *error)
{
    std::lock_guard lock(m_mutex);
    std::string name = requested;
    for (int n = 0; name.empty(); ++n) {
        if (m_instanceNames.count(typeName + std::to_string(n)) == 0)
            name = typeName + std::to_string(n);
    }
    if (!m_instanceNames.insert(name).second) {
        *error = "create_component: instance name '" + name + "' is already in use";
        return {};
    }
    return name;
}

std::optional<ComponentFactory> Manager::factoryFor(const CreateRequest &request, std::string *why)
{
    // A type of an installed package: the module of the version asked for, else of the newest.
    const std::vector<std::string> installed = installedModuleDirs(request.packageVersion);
    const std::string packaged = moduleInDirs(request.implementationId, installed);
    if (!packaged.empty())
        return factoryOfModule(request, packaged);
    if (!request.packageVersion.empty()) {
        *why = "create_component: no installed package of version " + request.packageVersion
            + " provides type '" + request.implementationId + "'";
        return std::nullopt;
    }
    {
        std::lock_guard lock(m_mutex);
        if (const ComponentFactory *factory = findFactory(request))
            return *factory;
    }
    // A type nobody registered yet may be in a loadable module of the load path: `<Type>.so` (or .py), as
    // the Builder and OpenRTP name them, else the module that lists it (as OpenRTM-aist's
    // manager.modules.search_auto). Load it, then look again.
    std::string module = findModuleFile(request.implementationId);
    if (module.empty()) {
        for (const Properties &loadable : loadableModules()) {
            if (module.empty() && isRequestedType(loadable, request))
                module = loadable.value("module_file_path");
        }
    }
    std::string loadError;
    if (module.empty() || !loadRequestedModule(module, std::string(), &loadError))
        return std::nullopt;
    std::lock_guard lock(m_mutex);
    const ComponentFactory *factory = findFactory(request);
    return factory ? std::optional<ComponentFactory>(*factory) : std::nullopt;
}

bool Manager::readConfigFiles(Properties *properties, const std::string &instance, const std::string &requestedFile,
                              std::string *error)
{
    // OpenRTM's per-component settings: for the type, then for the instance, rtc.conf's
    // `<category>.<name>.config_file` and then rtc.conf's own `<category>.<name>.*` keys
    // (`example.Throughput_py.conf.default.maxsize: 300`); last the request's own `config_file`.
    const Properties config = configuration();
    const std::string category = properties->value("category");
    for (const std::string &name : {properties->value("type_name"), instance}) {
        const std::string prefix = category + '.' + name;
        if (!mergeConfigFile(properties, instance, config.value(prefix + ".config_file"), false, error))
            return false;
        Properties keys = config.subtree(prefix);
        keys.remove("config_file");
        properties->merge(keys);
    }
    return mergeConfigFile(properties, instance, requestedFile, true, error);
}

bool Manager::mergeConfigFile(Properties *properties, const std::string &instance, const std::string &file,
                              bool requested, std::string *error)
{
    if (file.empty())
        return true;
    std::ifstream in(file);
    if (!in && requested) {
        *error = "create_component: cannot read config_file '" + file + "'";
        return false;
    }
    if (!in) {
        // As in OpenRTM-aist, a file named in rtc.conf that is not there only costs its settings.
        std::cerr << programName() << ": " << instance << ": cannot read config_file '" << file << "'" << std::endl;
        return true;
    }
    std::stringstream text;
    text << in.rdbuf();
    properties->merge(Properties::parseConf(text.str()));
    return true;
}

RTC::RTObject_ptr Manager::createLocal(const CreateRequest &request, std::string *error)
{
    // A manager that only loads modules (rtmanager --module-profile) never serves: a component
    // made there would wait for ever on its own calls.
    if (CORBA::is_nil(m_poa)) {
        fail("create_component: this manager does not serve components (not started)", error);
        return RTC::RTObject::_nil();
    }
    // Against exhaustion: a caller creating without end is refused, the manager serves on.
    const double limit = configNumber("manager.components.max", DefaultComponentLimit);
    size_t hosted = 0;
    {
        std::lock_guard lock(m_mutex);
        hosted = m_components.size();
    }
    if (double(hosted) >= limit) {
        fail("create_component: this manager hosts " + std::to_string(hosted)
                 + " components, as many as manager.components.max allows",
             error);
        return RTC::RTObject::_nil();
    }
    std::string why = "create_component: unknown component type '" + request.implementationId + "'";
    const std::optional<ComponentFactory> factory = factoryFor(request, &why);
    if (!factory) {
        fail(why, error);
        return RTC::RTObject::_nil();
    }
    Properties properties = factory->profile;
    const Properties config = configuration();
    for (const char *key : {"exec_cxt.periodic.rate", "exec_cxt.periodic.type", "exec_cxt.transition_timeout"}) {
        if (config.contains(key))
            properties.set(key, config.value(key));
    }
    if (m_hooks.preConfigure)
        m_hooks.preConfigure(properties);
    std::string problem;
    const std::string instance = reserveInstanceName(request.properties.value("instance_name"),
                                                     properties.value("type_name", request.implementationId), &problem);
    if (instance.empty()) {
        fail(problem, error);
        return RTC::RTObject::_nil();
    }
    bool configured = readConfigFiles(&properties, instance, request.properties.value("config_file"), &problem);
    properties.merge(request.properties);
    // As OpenRTM-aist's manager: a composite's exported ports given with the request are its
    // default configuration's, in today's `<instance>.<port>` form.
    if (request.properties.contains("exported_ports")) {
        const std::string ports = exportedPortList(request.properties.value("exported_ports"));
        properties.set("exported_ports", ports);
        properties.set("conf.default.exported_ports", ports);
    }
    properties.set("instance_name", instance);
    if (configured) {
        // Refused before the component exists: its type of execution context must be one we make.
        const std::string refusal =
            ExecutionContextFactory::instance().check(ExecutionContextFactory::typeOf(properties));
        if (!refusal.empty()) {
            problem = "create_component: " + instance + ": " + refusal;
            configured = false;
        }
    }
    if (configured && m_hooks.postConfigure)
        m_hooks.postConfigure(properties);
    auto component = std::make_unique<Component>();
    component->instanceName = instance;
    component->modulePath = factory->modulePath;
    if (configured)
        component->servant = factory->create(m_poa);
    Component *record = component.get();
    {
        std::lock_guard lock(m_mutex);
        if (configured)
            m_components.push_back(std::move(component));
        else
            m_instanceNames.erase(instance);
    }
    if (!configured) {
        fail(problem, error);
        return RTC::RTObject::_nil();
    }
    return initializeComponent(record, properties, error);
}

RTC::RTObject_ptr Manager::initializeComponent(Component *record, const Properties &properties, std::string *error)
{
    record->servant->setProperties(properties);
    record->reference = record->servant->reference();
    if (m_hooks.preInitialize)
        m_hooks.preInitialize();
    const RTC::ReturnCode_t result = record->servant->initialize();
    if (m_hooks.postInitialize)
        m_hooks.postInitialize();
    if (result != RTC::RTC_OK) {
        const std::string instance = record->instanceName;
        const std::string reason = record->servant->initializeError();
        forget(record->servant);
        fail("create_component: " + instance + " failed to initialize" + (reason.empty() ? "" : ": " + reason),
             error);
        return RTC::RTObject::_nil();
    }
    record->servant->setExitHandler([this](RtObject *servant) { componentExited(servant); });
    registerNames(*record);
    if (m_hooks.postCreate)
        m_hooks.postCreate(record->servant);
    return RTC::RTObject::_duplicate(record->reference);
}

void Manager::registerNames(Component &component)
{
    Properties values = component.servant->properties();
    values.set("manager_name", m_instanceName);
    std::vector<std::string> errors;
    std::vector<std::string> paths =
        NamingRegistrar::expand(m_config.value("naming.formats", "%h.host_cxt/%n.rtc"), values);
    if (m_hooks.preNaming)
        m_hooks.preNaming(component.servant, paths, true);
    for (const std::string &path : paths) {
        m_naming->bind(path, component.reference, &errors);
        component.names.push_back(path);
    }
    for (const std::string &message : errors)
        std::cerr << programName() << ": " << message << std::endl;
    if (m_hooks.postNaming)
        m_hooks.postNaming(component.servant, component.names, true);
}

void Manager::keepNamesBound()
{
    const std::chrono::duration<double> interval(std::max(0.05, configNumber("naming.update.interval", 10.0)));
    const bool everyRound = m_config.isYes("naming.update.rebind", false);
    std::unique_lock lock(m_mutex);
    while (!m_stopping) {
        // Woken early only to stop (the variable also tells of slaves).
        const auto next = std::chrono::steady_clock::now() + interval;
        if (m_slavesChanged.wait_until(lock, next, [this] { return m_stopping; }))
            return;
        lock.unlock();
        // A component deleted meanwhile has its names unbound after this round, never before.
        std::lock_guard naming(m_namingMutex);
        lock.lock();
        std::vector<std::pair<std::string, CORBA::Object_var>> names;
        for (const std::string &path : m_ownNames)
            names.emplace_back(path, CORBA::Object::_duplicate(m_self));
        for (const auto &component : m_components) {
            for (const std::string &path : component->names)
                names.emplace_back(path, CORBA::Object::_duplicate(component->reference));
        }
        lock.unlock();
        for (const std::string &server : m_naming->servers()) {
            if (names.empty())
                break;
            if (!everyRound
                && m_naming->lookUp(server, names.front().first) != NamingRegistrar::Lookup::Missing)
                continue;
            std::vector<std::string> errors;
            for (const auto &[path, object] : names)
                m_naming->bindOn(server, path, object, &errors);
            if (!everyRound)
                std::cerr << programName() << ": name server " << server << " did not have this manager's names: "
                          << names.size() - errors.size() << " of " << names.size() << " bound again" << std::endl;
        }
        lock.lock();
    }
}

void Manager::componentExited(RtObject *servant)
{
    forget(servant);
    // OpenRTM's manager.shutdown_on_nortcs also holds when the last component exits by itself
    // (rtctl exit, or a component calling exit(), as OpenRTM-aist's Throughput example does).
    if (m_config.isYes("manager.shutdown_on_nortcs") && components().length() == 0)
        shutdown();
}

void Manager::forget(RtObject *servant)
{
    std::unique_ptr<Component> removed;
    {
        std::lock_guard lock(m_mutex);
        auto it = std::find_if(m_components.begin(), m_components.end(),
                               [servant](const auto &c) { return c->servant == servant; });
        if (it == m_components.end())
            return;
        removed = std::move(*it);
        m_components.erase(it);
        m_instanceNames.erase(removed->instanceName);
    }
    if (m_hooks.preNaming)
        m_hooks.preNaming(removed->servant, removed->names, false);
    {
        std::lock_guard naming(m_namingMutex);
        for (const std::string &path : removed->names)
            m_naming->unbind(path);
    }
    if (m_hooks.postNaming)
        m_hooks.postNaming(removed->servant, removed->names, false);
    releaseServant(m_poa, removed->servant);
}

bool Manager::adoptComponent(RtObject *servant, std::string *error)
{
    if (servant == nullptr)
        return fail("register_component: no component", error);
    const std::string instance = servant->instanceName();
    if (instance.empty())
        return fail("register_component: the component has no instance_name", error);
    auto component = std::make_unique<Component>();
    component->servant = servant;
    component->instanceName = instance;
    component->reference = servant->reference();
    Component *record = component.get();
    bool taken = false;
    {
        std::lock_guard lock(m_mutex);
        taken = !m_instanceNames.insert(instance).second;
    }
    if (taken)
        return fail("register_component: instance name '" + instance + "' is taken", error);
    {
        std::lock_guard lock(m_mutex);
        // The creator's reference becomes the manager's: the object goes when it exits, as one
        // the manager made.
        m_components.push_back(std::move(component));
    }
    servant->setExitHandler([this](RtObject *s) { componentExited(s); });
    registerNames(*record);
    return true;
}

bool Manager::releaseComponent(RtObject *servant)
{
    std::unique_ptr<Component> removed;
    {
        std::lock_guard lock(m_mutex);
        auto it = std::find_if(m_components.begin(), m_components.end(),
                               [servant](const auto &c) { return c->servant == servant; });
        if (it == m_components.end())
            return false;
        removed = std::move(*it);
        m_components.erase(it);
        m_instanceNames.erase(removed->instanceName);
    }
    servant->setExitHandler({});
    for (const std::string &path : removed->names)
        m_naming->unbind(path);
    return true;
}

bool Manager::deleteComponent(const std::string &instanceName, std::string *error)
{
    RtObject *servant = nullptr;
    {
        std::lock_guard lock(m_mutex);
        for (const auto &component : m_components) {
            if (component->instanceName == instanceName)
                servant = component->servant;
        }
    }
    if (!servant)
        return fail("delete_component: no component named '" + instanceName + "'", error);
    if (servant->exit() != RTC::RTC_OK)
        forget(servant);
    // OpenRTM's manager.shutdown_on_nortcs: the last deleted component takes the manager along.
    if (m_config.isYes("manager.shutdown_on_nortcs") && components().length() == 0)
        shutdown();
    return true;
}

RTC::RTCList Manager::components()
{
    std::lock_guard lock(m_mutex);
    RTC::RTCList list;
    for (const auto &component : m_components) {
        if (CORBA::is_nil(component->reference))
            continue;
        const CORBA::ULong n = list.length();
        list.length(n + 1);
        list[n] = RTC::RTObject::_duplicate(component->reference);
    }
    return list;
}

RTC::RTCList Manager::componentsByName(const std::string &name)
{
    const std::size_t slash = name.find('/');
    const std::string category = slash == std::string::npos ? std::string() : name.substr(0, slash);
    const std::string instance = slash == std::string::npos ? name : name.substr(slash + 1);
    std::lock_guard lock(m_mutex);
    RTC::RTCList list;
    for (const auto &component : m_components) {
        if (component->instanceName != instance || CORBA::is_nil(component->reference))
            continue;
        if (slash != std::string::npos && category != "*"
            && (!component->servant || component->servant->properties().value("category") != category))
            continue;
        const CORBA::ULong n = list.length();
        list.length(n + 1);
        list[n] = RTC::RTObject::_duplicate(component->reference);
    }
    return list;
}

Properties Manager::configuration()
{
    std::lock_guard lock(m_mutex);
    return m_config;
}

namespace {

/// Configuration keys a remote set_configuration may not change (prefixes), and the suffix of the
/// per-component configuration file keys (`<category>.<type>.config_file`).
constexpr std::array<std::string_view, 9> LocalOnlyPrefixes
    = {"manager.modules.", "manager.packages.", "manager.preload.", "manager.components.", "manager.slaves.",
       "manager.local_service.", "manager.is_master", "corba.", "logger.file_name"};
constexpr std::string_view ConfigFileSuffix = ".config_file";

bool isLocalOnlyKey(const std::string &key)
{
    const auto startsWith = [&key](std::string_view prefix) { return key.compare(0, prefix.size(), prefix) == 0; };
    const bool configFile = key.size() >= ConfigFileSuffix.size()
                            && key.compare(key.size() - ConfigFileSuffix.size(), ConfigFileSuffix.size(), ConfigFileSuffix) == 0;
    return configFile || std::any_of(LocalOnlyPrefixes.begin(), LocalOnlyPrefixes.end(), startsWith);
}

} // namespace

bool Manager::setConfiguration(const std::string &key, const std::string &value)
{
    if (key.empty())
        return fail("set_configuration: no key given", nullptr);
    if (isLocalOnlyKey(key))
        return fail("set_configuration: '" + key + "' is taken from the manager's own configuration only", nullptr);
    std::lock_guard lock(m_mutex);
    m_config.set(key, value);
    return true;
}

Properties Manager::profile()
{
    // As OpenRTM-aist's: the configuration's manager.* keys without their prefix (rtshell and
    // OpenRTP show naming_formats, modules.load_path …), and what this runtime adds.
    const Properties config = configuration();
    Properties p = config.subtree("manager");
    // What a deployment planner needs (docs/planner.md): the host's facts and the operator's
    // node.* facts (devices, role …) from the configuration.
    p.merge(hostFacts());
    const Properties node = config.subtree("node");
    for (const auto &[key, value] : node.entries())
        p.set("node." + key, value);
    std::string packages;
    for (const std::string &name : installedPackages())
        packages += (packages.empty() ? "" : ",") + name;
    p.set("rtstudio.packages", packages);
    p.set("instance_name", m_instanceName);
    p.set("name", m_config.value("manager.name", "manager"));
    p.set("pid", std::to_string(getpid()));
    p.set("address", m_address);
    p.set("is_master", m_isMaster ? "YES" : "NO");
    p.set("last_error", lastError());
    {
        std::lock_guard lock(m_mutex);
        for (const auto &[request, reason] : m_refusals)
            p.set("rtstudio.create_error." + request, reason);
    }
    // Tells clients they may send create_component calls at once (rtctl mgr does): names, ports
    // and slave processes are handed out safely. Other managers lack the key and get them in turn.
    p.set("rtstudio.concurrent_create", "YES");
    return p;
}

RTM::Manager_ptr Manager::reference()
{
    return RTM::Manager::_duplicate(m_self);
}

double Manager::configNumber(const std::string &key, double fallback) const
{
    constexpr double largest = 1e9;
    std::string problem;
    const double value = m_config.number(key, fallback, &problem);
    if (!problem.empty())
        std::cerr << programName() << ": " << problem << std::endl;
    if (value < 0 || value > largest) {
        std::cerr << programName() << ": " << key << ": " << value << " is out of range (0 to "
                  << largest << ")" << std::endl;
        return std::clamp(value, 0.0, largest);
    }
    return value;
}

} // namespace Runtime
