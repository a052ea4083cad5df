// SPDX-License-Identifier: MIT
// RTC::NamingManager and RTM::ManagerServant over the runtime's naming registrar and manager.
#include <rtm/Manager.h>
#include <rtm/ManagerServant.h>
#include <rtm/NamingManager.h>

#include <corbautil.h>
#include <manager.h>
#include <namingregistrar.h>

#include <algorithm>
#include <iostream>

namespace RTC {

namespace {

/// The name server's root context at @p endpoint (`host[:port]`); nil when it does not answer.
CosNaming::NamingContext_ptr rootContext(CORBA::ORB_ptr orb, const std::string &endpoint)
{
    const std::string address = endpoint.find(':') == std::string::npos ? endpoint + ":2809" : endpoint;
    try {
        CORBA::Object_var object = orb->string_to_object(("corbaloc:iiop:" + address + "/NameService").c_str());
        CosNaming::NamingContext_var root = CosNaming::NamingContext::_narrow(object);
        if (CORBA::is_nil(root) || root->_non_existent())
            return CosNaming::NamingContext::_nil();
        return root._retn();
    } catch (const CORBA::Exception &) {
        return CosNaming::NamingContext::_nil();
    }
}

/// `a.kind/b.kind` as a CosNaming name.
CosNaming::Name toName(const std::string &path)
{
    CosNaming::Name name;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t slash = path.find('/', start);
        const std::string part = path.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
        if (!part.empty()) {
            const std::size_t dot = part.rfind('.');
            const CORBA::ULong n = name.length();
            name.length(n + 1);
            name[n].id = CORBA::string_dup(part.substr(0, dot).c_str());
            name[n].kind = CORBA::string_dup(dot == std::string::npos ? "" : part.substr(dot + 1).c_str());
        }
        if (slash == std::string::npos)
            break;
        start = slash + 1;
    }
    return name;
}

RTM::Manager_ptr runtimeManager()
{
    Runtime::Manager *runtime = Manager::instance().runtime();
    return runtime != nullptr ? runtime->reference() : RTM::Manager::_nil();
}

} // namespace

// --- NamingOnCorba ---

NamingOnCorba::NamingOnCorba(CORBA::ORB_ptr orb, const char *names)
    : rtclog("NamingOnCorba")
    , m_orb(CORBA::ORB::_duplicate(orb))
    , m_endpoint(names != nullptr ? names : "")
    , m_registrar(new Runtime::NamingRegistrar({m_endpoint}))
{
}

NamingOnCorba::~NamingOnCorba()
{
    delete m_registrar;
}

void NamingOnCorba::bind(const char *name, CORBA::Object_ptr object)
{
    if (name == nullptr)
        return;
    std::vector<std::string> errors;
    if (!m_registrar->bind(name, object, &errors)) {
        for (const std::string &error : errors) {
            RTC_ERROR_STR(error);
            std::cerr << error << std::endl;
        }
    }
}

void NamingOnCorba::bindObject(const char *name, const RTObject_impl *rtobj)
{
    if (rtobj != nullptr) {
        RTC::RTObject_var ref = rtobj->getObjRef();
        bind(name, ref);
    }
}

void NamingOnCorba::bindObject(const char *name, const PortBase *port)
{
    if (port != nullptr) {
        RTC::PortService_var ref = const_cast<PortBase *>(port)->reference();
        bind(name, ref);
    }
}

void NamingOnCorba::bindObject(const char *name, const RTM::ManagerServant *mgr)
{
    if (mgr != nullptr) {
        RTM::Manager_var ref = mgr->getObjRef();
        bind(name, ref);
    }
}

void NamingOnCorba::unbindObject(const char *name)
{
    if (name != nullptr)
        m_registrar->unbind(name);
}

bool NamingOnCorba::isAlive()
{
    CosNaming::NamingContext_var root = rootContext(m_orb, m_endpoint);
    return !CORBA::is_nil(root);
}

RTC::RTCList NamingOnCorba::string_to_component(std::string name)
{
    RTC::RTCList list;
    // rtcname://host:port/ctx.host_cxt/Name addresses the component bound as Name.rtc in the name
    // server at host:port (`*`: this one); a bare path is looked up here as it is.
    std::string endpoint = m_endpoint;
    const std::string scheme = "rtcname://";
    if (name.compare(0, scheme.size(), scheme) == 0) {
        const std::string rest = name.substr(scheme.size());
        const std::size_t slash = rest.find('/');
        if (slash == std::string::npos || slash + 1 == rest.size())
            return list;
        if (rest.compare(0, slash, "*") != 0)
            endpoint = rest.substr(0, slash);
        name = rest.substr(slash + 1) + ".rtc";
    }
    CosNaming::NamingContext_var root = rootContext(m_orb, endpoint);
    if (CORBA::is_nil(root))
        return list;
    try {
        CORBA::Object_var object = root->resolve(toName(name));
        RTC::RTObject_var rtc = RTC::RTObject::_narrow(object);
        if (!CORBA::is_nil(rtc)) {
            list.length(1);
            list[0] = rtc._retn();
        }
    } catch (const CORBA::Exception &) {
        // Not bound there: no component.
    }
    return list;
}

// --- NamingOnManager ---

NamingOnManager::NamingOnManager(CORBA::ORB_ptr orb, Manager *mgr)
    : rtclog("NamingOnManager")
    , m_orb(orb)
    , m_mgr(mgr)
{
}

// The manager finds its components by instance name itself: there is no table to write.
void NamingOnManager::bindObject(const char *, const RTObject_impl *) {}
void NamingOnManager::bindObject(const char *, const PortBase *) {}
void NamingOnManager::bindObject(const char *, const RTM::ManagerServant *) {}
void NamingOnManager::unbindObject(const char *) {}

bool NamingOnManager::isAlive()
{
    return true;
}

RTC::RTCList NamingOnManager::string_to_component(std::string name)
{
    // rtcloc://host:port/category/name addresses another manager; a bare name is ours.
    const std::string scheme = "rtcloc://";
    if (name.compare(0, scheme.size(), scheme) == 0) {
        const std::string rest = name.substr(scheme.size());
        const std::size_t slash = rest.find('/');
        RTM::Manager_var manager = getManager(rest.substr(0, slash));
        if (CORBA::is_nil(manager) || slash == std::string::npos)
            return RTC::RTCList();
        try {
            RTC::RTCList_var list = manager->get_components_by_name(rest.substr(slash + 1).c_str());
            return list.in();
        } catch (const CORBA::Exception &) {
            return RTC::RTCList();
        }
    }
    Runtime::Manager *runtime = m_mgr != nullptr ? m_mgr->runtime() : nullptr;
    return runtime != nullptr ? runtime->componentsByName(name) : RTC::RTCList();
}

RTM::Manager_ptr NamingOnManager::getManager(const std::string &name)
{
    return Manager::instance().getManagerServant().findManager(name);
}

// --- NamingManager ---

NamingManager::NamingManager(Manager *manager)
    : m_manager(manager)
    , rtclog("NamingManager")
{
}

NamingManager::~NamingManager()
{
    unbindAll();
    for (NamingService *service : m_names)
        delete service;
    for (Comps *c : m_compNames)
        delete c;
    for (Port *p : m_portNames)
        delete p;
    for (Mgr *m : m_mgrNames)
        delete m;
}

NamingBase *NamingManager::createNamingObj(const char *method, const char *name_server)
{
    const std::string kind = method != nullptr ? method : "";
    CORBA::ORB_var orb = Runtime::theOrb();
    if (kind == "corba")
        return new NamingOnCorba(orb, name_server);
    if (kind == "manager")
        return new NamingOnManager(orb, m_manager);
    const std::string message = "NamingManager: unknown naming method '" + kind + "' (known: corba, manager)";
    RTC_ERROR_STR(message);
    std::cerr << message << std::endl;
    return nullptr;
}

void NamingManager::registerNameServer(const char *method, const char *name_server)
{
    NamingBase *naming = createNamingObj(method, name_server);
    if (naming == nullptr)
        return;
    bindCompsTo(naming);
    std::lock_guard<std::mutex> lock(m_namesMutex);
    m_names.push_back(new NamingService(method, name_server != nullptr ? name_server : "", naming));
}

void NamingManager::bindObject(const char *name, const PortBase *port)
{
    {
        std::lock_guard<std::mutex> lock(m_namesMutex);
        for (NamingService *service : m_names)
            service->ns->bindObject(name, port);
    }
    registerPortName(name, port);
}

void NamingManager::bindObject(const char *name, const RTObject_impl *rtobj)
{
    {
        std::lock_guard<std::mutex> lock(m_namesMutex);
        for (NamingService *service : m_names)
            service->ns->bindObject(name, rtobj);
    }
    registerCompName(name, rtobj);
}

void NamingManager::bindObject(const char *name, const RTM::ManagerServant *mgr)
{
    {
        std::lock_guard<std::mutex> lock(m_namesMutex);
        for (NamingService *service : m_names)
            service->ns->bindObject(name, mgr);
    }
    registerMgrName(name, mgr);
}

void NamingManager::update()
{
    std::lock_guard<std::mutex> lock(m_namesMutex);
    for (NamingService *service : m_names)
        bindCompsTo(service->ns);
}

void NamingManager::bindCompsTo(NamingBase *ns)
{
    {
        std::lock_guard<std::mutex> lock(m_compNamesMutex);
        for (Comps *c : m_compNames)
            ns->bindObject(c->name.c_str(), c->rtobj);
    }
    {
        std::lock_guard<std::mutex> lock(m_portNamesMutex);
        for (Port *p : m_portNames)
            ns->bindObject(p->name.c_str(), p->port);
    }
    std::lock_guard<std::mutex> lock(m_mgrNamesMutex);
    for (Mgr *m : m_mgrNames)
        ns->bindObject(m->name.c_str(), m->mgr);
}

void NamingManager::unbindObject(const char *name)
{
    if (name == nullptr)
        return;
    {
        std::lock_guard<std::mutex> lock(m_namesMutex);
        for (NamingService *service : m_names)
            service->ns->unbindObject(name);
    }
    unregisterCompName(name);
    unregisterPortName(name);
    unregisterMgrName(name);
}

void NamingManager::unbindAll()
{
    std::vector<std::string> names;
    {
        std::lock_guard<std::mutex> lock(m_compNamesMutex);
        for (Comps *c : m_compNames)
            names.push_back(c->name);
    }
    {
        std::lock_guard<std::mutex> lock(m_portNamesMutex);
        for (Port *p : m_portNames)
            names.push_back(p->name);
    }
    {
        std::lock_guard<std::mutex> lock(m_mgrNamesMutex);
        for (Mgr *m : m_mgrNames)
            names.push_back(m->name);
    }
    for (const std::string &name : names)
        unbindObject(name.c_str());
}

std::vector<RTObject_impl *> NamingManager::getObjects()
{
    std::vector<RTObject_impl *> objects;
    std::lock_guard<std::mutex> lock(m_compNamesMutex);
    for (Comps *c : m_compNames) {
        auto *rtobj = const_cast<RTObject_impl *>(c->rtobj);
        if (std::find(objects.begin(), objects.end(), rtobj) == objects.end())
            objects.push_back(rtobj);
    }
    return objects;
}

RTCList NamingManager::string_to_component(const std::string &name)
{
    std::lock_guard<std::mutex> lock(m_namesMutex);
    for (NamingService *service : m_names) {
        RTCList list = service->ns->string_to_component(name);
        if (list.length() > 0)
            return list;
    }
    return RTCList();
}

namespace {

template <typename Entry, typename Object>
void remember(std::vector<Entry *> &entries, std::mutex &mutex, const char *name, Object object)
{
    if (name == nullptr)
        return;
    std::lock_guard<std::mutex> lock(mutex);
    for (Entry *entry : entries) {
        if (entry->name == name)
            return;
    }
    entries.push_back(new Entry(name, object));
}

template <typename Entry>
void forget(std::vector<Entry *> &entries, std::mutex &mutex, const char *name)
{
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = entries.begin(); it != entries.end(); ++it) {
        if ((*it)->name == name) {
            delete *it;
            entries.erase(it);
            return;
        }
    }
}

} // namespace

void NamingManager::registerCompName(const char *name, const RTObject_impl *rtobj)
{
    remember(m_compNames, m_compNamesMutex, name, rtobj);
}

void NamingManager::registerPortName(const char *name, const PortBase *port)
{
    remember(m_portNames, m_portNamesMutex, name, port);
}

void NamingManager::registerMgrName(const char *name, const RTM::ManagerServant *mgr)
{
    remember(m_mgrNames, m_mgrNamesMutex, name, mgr);
}

void NamingManager::unregisterCompName(const char *name)
{
    forget(m_compNames, m_compNamesMutex, name);
}

void NamingManager::unregisterPortName(const char *name)
{
    forget(m_portNames, m_portNamesMutex, name);
}

void NamingManager::unregisterMgrName(const char *name)
{
    forget(m_mgrNames, m_mgrNamesMutex, name);
}

} // namespace RTC

namespace RTM {

const char *CompParam::prof_list[CompParam::prof_list_size]
    = {"RTC", "vendor", "category", "implementation_id", "language", "version"};

CompParam::CompParam(std::string module_name)
    : m_type("RTC")
    , m_language("C++")
{
    module_name = module_name.substr(0, module_name.find('?'));
    const coil::vstring parts = coil::split(module_name, ":");
    if (parts.size() < prof_list_size) {
        m_impl_id = module_name;
        return;
    }
    m_type = parts[0];
    m_vendor = parts[1];
    m_category = parts[2];
    m_impl_id = parts[3];
    if (!parts[4].empty())
        m_language = parts[4];
    m_version = parts[5];
}

CompParam::~CompParam() = default;

std::string CompParam::vendor()
{
    return m_vendor;
}

std::string CompParam::category()
{
    return m_category;
}

std::string CompParam::impl_id()
{
    return m_impl_id;
}

std::string CompParam::language()
{
    return m_language;
}

std::string CompParam::version()
{
    return m_version;
}

ManagerServant::ManagerServant() = default;
ManagerServant::~ManagerServant() = default;

RTM::Manager_ptr ManagerServant::getObjRef() const
{
    return RTC::runtimeManager();
}

bool ManagerServant::createINSManager()
{
    RTM::Manager_var self = getObjRef();
    return !CORBA::is_nil(self);
}

RTM::Manager_ptr ManagerServant::findManager(const std::string &host_port)
{
    try {
        CORBA::ORB_var orb = Runtime::theOrb();
        CORBA::Object_var object = orb->string_to_object(("corbaloc:iiop:" + host_port + "/manager").c_str());
        RTM::Manager_var manager = RTM::Manager::_narrow(object);
        if (CORBA::is_nil(manager) || manager->_non_existent())
            return RTM::Manager::_nil();
        return manager._retn();
    } catch (const CORBA::Exception &) {
        return RTM::Manager::_nil();
    }
}

CORBA::Boolean ManagerServant::is_master()
{
    Runtime::Manager *runtime = RTC::Manager::instance().runtime();
    return runtime != nullptr && runtime->isMaster();
}

RTM::ManagerList *ManagerServant::get_master_managers()
{
    Runtime::Manager *runtime = RTC::Manager::instance().runtime();
    return new RTM::ManagerList(runtime != nullptr ? runtime->masters() : RTM::ManagerList());
}

RTM::ManagerList *ManagerServant::get_slave_managers()
{
    Runtime::Manager *runtime = RTC::Manager::instance().runtime();
    return new RTM::ManagerList(runtime != nullptr ? runtime->slaves() : RTM::ManagerList());
}

RTC::RTCList *ManagerServant::get_components()
{
    Runtime::Manager *runtime = RTC::Manager::instance().runtime();
    return new RTC::RTCList(runtime != nullptr ? runtime->components() : RTC::RTCList());
}

RTC::RTCList *ManagerServant::get_components_by_name(const char *name)
{
    Runtime::Manager *runtime = RTC::Manager::instance().runtime();
    return new RTC::RTCList(runtime != nullptr && name != nullptr ? runtime->componentsByName(name)
                                                                  : RTC::RTCList());
}

} // namespace RTM
