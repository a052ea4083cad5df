// SPDX-License-Identifier: MIT
// The manager's internal classes OpenRTM-aist code reaches: numbering policies, the factory
// initialisation, ManagerConfig, ModuleManager and RTC_impl::ExecutionContextProfile.
#include <rtm/DefaultConfiguration.h>
#include <rtm/ECFactory.h>
#include <rtm/ExecutionContextProfile.h>
#include <rtm/ExtTrigExecutionContext.h>
#include <rtm/FactoryInit.h>
#include <rtm/ManagerConfig.h>
#include <rtm/ManagerServant.h>
#include <rtm/ModuleManager.h>
#include <rtm/NamingManager.h>
#include <rtm/NamingServiceNumberingPolicy.h>
#include <rtm/NodeNumberingPolicy.h>
#include <rtm/NumberingPolicy.h>
#include <rtm/OpenHRPExecutionContext.h>
#include <rtm/PeriodicExecutionContext.h>
#include <rtm/RTObject.h>
#include <rtm/SimulatorExecutionContext.h>

#include <coil/File.h>
#include <coil/stringutil.h>

#include "sdkinternal.h"

#include <hostfacts.h>
#include <managerconfig.h>
#include <namingregistrar.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <stdexcept>

// --- Numbering policies ---

namespace RTM {

std::string ProcessUniquePolicy::onCreate(void *obj)
{
    // A freed slot (null) is reused before the list grows.
    auto freeSlot = std::find(m_objects.begin(), m_objects.end(), nullptr);
    if (freeSlot != m_objects.end()) {
        *freeSlot = obj;
        return std::to_string(freeSlot - m_objects.begin());
    }
    m_objects.push_back(obj);
    ++m_num;
    return std::to_string(m_objects.size() - 1);
}

void ProcessUniquePolicy::onDelete(void *obj)
{
    m_objects[std::size_t(find(obj))] = nullptr;
    --m_num;
}

long int ProcessUniquePolicy::find(void *obj)
{
    auto it = std::find(m_objects.begin(), m_objects.end(), obj);
    if (obj == nullptr || it == m_objects.end())
        throw ObjectNotFound();
    return long(it - m_objects.begin());
}

namespace {

/// The lowest N for which @p taken says `<type>N` is free.
template <typename Taken>
std::string lowestFree(void *obj, Taken taken)
{
    auto *component = static_cast<RTC::RTObject_impl *>(obj);
    const std::string type = component != nullptr ? component->getTypeName() : "";
    for (long n = 0;; ++n) {
        if (!taken(type + std::to_string(n)))
            return std::to_string(n);
    }
}

void forgetObject(std::vector<void *> &objects, void *obj)
{
    auto it = std::find(objects.begin(), objects.end(), obj);
    if (it == objects.end())
        throw NumberingPolicyBase::ObjectNotFound();
    objects.erase(it);
}

} // namespace

NodeNumberingPolicy::NodeNumberingPolicy()
    : m_mgr(&RTC::Manager::instance())
{
}

std::string NodeNumberingPolicy::onCreate(void *obj)
{
    m_objects.push_back(obj);
    return lowestFree(obj, [this](const std::string &name) { return find(name); });
}

void NodeNumberingPolicy::onDelete(void *obj)
{
    forgetObject(m_objects, obj);
}

bool NodeNumberingPolicy::find(std::string name)
{
    if (m_mgr->getComponent(name.c_str()) != nullptr)
        return true;
    ManagerServant &servant = m_mgr->getManagerServant();
    // The node: this manager's masters and every slave of them (or of this one, as a master).
    RTM::ManagerList_var masters = servant.get_master_managers();
    RTM::ManagerList managers;
    if (masters->length() == 0) {
        RTM::ManagerList_var slaves = servant.get_slave_managers();
        managers = slaves.in();
    }
    for (CORBA::ULong i = 0; i < masters->length(); ++i) {
        const CORBA::ULong n = managers.length();
        managers.length(n + 1);
        managers[n] = RTM::Manager::_duplicate(masters[i]);
        try {
            RTM::ManagerList_var slaves = masters[i]->get_slave_managers();
            for (CORBA::ULong j = 0; j < slaves->length(); ++j) {
                const CORBA::ULong m = managers.length();
                managers.length(m + 1);
                managers[m] = RTM::Manager::_duplicate(slaves[j]);
            }
        } catch (const CORBA::Exception &) {
        }
    }
    for (CORBA::ULong i = 0; i < managers.length(); ++i) {
        try {
            RTC::RTCList_var found = managers[i]->get_components_by_name(name.c_str());
            if (found->length() > 0)
                return true;
        } catch (const CORBA::Exception &) {
            // A manager that does not answer has no say.
        }
    }
    return false;
}

NamingServiceNumberingPolicy::NamingServiceNumberingPolicy()
    : m_mgr(&RTC::Manager::instance())
{
}

std::string NamingServiceNumberingPolicy::onCreate(void *obj)
{
    m_objects.push_back(obj);
    return lowestFree(obj, [this](const std::string &name) { return find(name); });
}

void NamingServiceNumberingPolicy::onDelete(void *obj)
{
    forgetObject(m_objects, obj);
}

bool NamingServiceNumberingPolicy::find(std::string name)
{
    Runtime::Properties values;
    values.set("instance_name", name);
    values.set("manager_name", m_mgr->getConfig().getProperty("manager.instance_name"));
    const std::string formats = m_mgr->getConfig().getProperty("naming.formats", "%h.host_cxt/%n.rtc");
    for (const std::string &path : Runtime::NamingRegistrar::expand(formats, values)) {
        if (m_mgr->getNaming()->string_to_component(path).length() > 0)
            return true;
    }
    return false;
}

void FactoryInit()
{
    PeriodicExecutionContextInit(nullptr);
    ExtTrigExecutionContextInit(nullptr);
    OpenHRPExecutionContextInit(nullptr);
    SimulatorExecutionContextInit(nullptr);
    ProcessUniquePolicyInit();
    NodeNumberingPolicyInit();
    NamingServiceNumberingPolicyInit();
}

} // namespace RTM

extern "C" {

void ProcessUniquePolicyInit()
{
    RTM::NumberingPolicyFactory::instance().addFactory(
        "process_unique", coil::Creator<RTM::NumberingPolicyBase, RTM::ProcessUniquePolicy>,
        coil::Destructor<RTM::NumberingPolicyBase, RTM::ProcessUniquePolicy>);
}

void NodeNumberingPolicyInit()
{
    RTM::NumberingPolicyFactory::instance().addFactory(
        "node_unique", coil::Creator<RTM::NumberingPolicyBase, RTM::NodeNumberingPolicy>,
        coil::Destructor<RTM::NumberingPolicyBase, RTM::NodeNumberingPolicy>);
}

void NamingServiceNumberingPolicyInit()
{
    RTM::NumberingPolicyFactory::instance().addFactory(
        "ns_unique", coil::Creator<RTM::NumberingPolicyBase, RTM::NamingServiceNumberingPolicy>,
        coil::Destructor<RTM::NumberingPolicyBase, RTM::NamingServiceNumberingPolicy>);
}
}

// --- ManagerConfig ---

namespace RTC {

const char *const ManagerConfig::config_file_path[] = {"./rtc.conf", "/etc/rtc.conf", "/etc/rtc/rtc.conf",
                                                       "/usr/local/etc/rtc.conf", "/usr/local/etc/rtc/rtc.conf",
                                                       nullptr};
const char *ManagerConfig::config_file_env = "RTC_MANAGER_CONFIG";

ManagerConfig::ManagerConfig() = default;

ManagerConfig::ManagerConfig(int argc, char **argv)
{
    init(argc, argv);
}

ManagerConfig::~ManagerConfig() = default;

void ManagerConfig::init(int argc, char **argv)
{
    parseArgs(argc, argv);
}

void ManagerConfig::parseArgs(int argc, char **argv)
{
    // The runtime reads the command line (and the file it names or finds) exactly as the
    // manager will; the result is kept whole.
    Runtime::Properties config;
    std::string error;
    if (!Runtime::parseManagerArguments(argc, argv, &config, &error))
        throw std::invalid_argument(error);
    m_argprop = Sdk::toCoil(config);
    m_isMaster = config.isYes("manager.is_master");
    m_configFile = config.value("config_file");
    if (m_configFile.empty())
        findConfigFile();
}

bool ManagerConfig::findConfigFile()
{
    m_configFile = Runtime::findConfigFile();
    return !m_configFile.empty();
}

void ManagerConfig::configure(coil::Properties &prop)
{
    prop << coil::Properties(default_config);
    prop << m_argprop;
    if (!m_configFile.empty())
        prop.setProperty("config_file", m_configFile);
    setSystemInformation(prop);
    if (m_isMaster)
        prop.setProperty("manager.is_master", "YES");
}

coil::Properties ManagerConfig::getConfig() const
{
    coil::Properties prop;
    const_cast<ManagerConfig *>(this)->configure(prop);
    return prop;
}

void ManagerConfig::setSystemInformation(coil::Properties &prop)
{
    // The same host facts rtmanager's profile gives.
    const Runtime::Properties facts = Runtime::osFacts();
    for (const auto &[key, value] : facts.entries())
        prop.setProperty(key, value);
    prop.setProperty("manager.pid", std::to_string(getpid()));
}

bool ManagerConfig::fileExist(const std::string &filename)
{
    std::ifstream in(filename);
    return bool(in);
}

// --- ModuleManager ---

namespace {

std::vector<std::string> pathList(const std::string &text)
{
    std::vector<std::string> paths;
    for (std::string path : coil::split(text, ",")) {
        path = coil::eraseBothEndsBlank(path);
        if (!path.empty())
            paths.push_back(path);
    }
    return paths;
}

} // namespace

ModuleManager::ModuleManager(coil::Properties &prop)
    : m_properties(prop)
    , m_loadPath(pathList(prop.getProperty(MOD_LOADPTH)))
    , m_configPath(pathList(prop.getProperty(CONFIG_PATH)))
    , m_downloadAllowed(coil::toBool(prop.getProperty(ALLOW_URL), "YES", "NO", false))
    , m_absoluteAllowed(coil::toBool(prop.getProperty(ALLOW_ABSPATH), "YES", "NO", false))
    , m_initFuncSuffix(prop.getProperty(INITFUNC_SFX, "Init"))
    , m_initFuncPrefix(prop.getProperty(INITFUNC_PFX))
{
}

ModuleManager::~ModuleManager()
{
    unloadAll();
}

std::string ModuleManager::load(const std::string &file_name)
{
    if (file_name.empty())
        throw InvalidArguments("Invalid file name.");
    if (file_name.find("://") != std::string::npos)
        throw NotAllowedOperation("Downloading modules is not supported: " + file_name);
    std::string path;
    if (coil::isAbsolutePath(file_name)) {
        if (!m_absoluteAllowed)
            throw NotAllowedOperation("Absolute path is not allowed: " + file_name);
        path = file_name;
    } else {
        path = findFile(file_name, m_loadPath);
    }
    if (path.empty() || !fileExist(path))
        throw FileNotFound(file_name);
    auto it = m_modules.find(path);
    if (it != m_modules.end())
        return path; // loaded already
    auto *module = new DLLEntity;
    if (module->dll.open(path.c_str()) != 0) {
        const std::string reason = coil::DynamicLib::error() ? coil::DynamicLib::error() : "dlopen failed";
        delete module;
        throw Error("DLL open failed: " + path + ": " + reason);
    }
    module->properties.setProperty("file_path", path);
    m_modules[path] = module;
    return path;
}

std::string ModuleManager::load(coil::Properties &prop)
{
    const std::string path = prop.getProperty("module_file_path");
    return load(path.empty() ? prop.getProperty("module_file_name") : path);
}

std::string ModuleManager::load(const std::string &file_name, const std::string &init_func)
{
    const std::string path = load(file_name);
    if (init_func.empty())
        return path;
    auto init = reinterpret_cast<ModuleInitFunc>(symbol(path, init_func));
    init(&Manager::instance());
    return path;
}

std::string ModuleManager::load(coil::Properties &prop, const std::string &init_func)
{
    const std::string path = prop.getProperty("module_file_path");
    return load(path.empty() ? prop.getProperty("module_file_name") : path, init_func);
}

void ModuleManager::unload(const std::string &file_name)
{
    std::string path = file_name;
    if (!coil::isAbsolutePath(path))
        path = findFile(file_name, m_loadPath);
    auto it = m_modules.find(path);
    if (it == m_modules.end())
        throw NotFound(file_name);
    it->second->dll.close();
    delete it->second;
    m_modules.erase(it);
}

void ModuleManager::unloadAll()
{
    for (auto &entry : m_modules) {
        entry.second->dll.close();
        delete entry.second;
    }
    m_modules.clear();
}

void *ModuleManager::symbol(const std::string &file_name, const std::string &func_name)
{
    auto it = m_modules.find(file_name);
    if (it == m_modules.end()) {
        const std::string path = findFile(file_name, m_loadPath);
        it = m_modules.find(path);
    }
    if (it == m_modules.end())
        throw ModuleNotFound(file_name);
    void *address = it->second->dll.symbol(func_name.c_str());
    if (address == nullptr)
        throw SymbolNotFound(func_name);
    return address;
}

void ModuleManager::setLoadpath(const std::vector<std::string> &load_path)
{
    m_loadPath = load_path;
}

void ModuleManager::addLoadpath(const std::vector<std::string> &load_path)
{
    m_loadPath.insert(m_loadPath.end(), load_path.begin(), load_path.end());
}

std::vector<coil::Properties> ModuleManager::getLoadedModules()
{
    std::vector<coil::Properties> modules;
    for (const auto &entry : m_modules)
        modules.push_back(entry.second->properties);
    return modules;
}

std::vector<coil::Properties> ModuleManager::getLoadableModules()
{
    std::vector<coil::Properties> modules;
    for (const std::string &dir : m_loadPath) {
        for (const std::string &name : coil::filelist(dir.c_str(), "*.so")) {
            coil::Properties module;
            module.setProperty("module_file_name", name);
            module.setProperty("module_file_path", dir + "/" + name);
            modules.push_back(module);
        }
    }
    return modules;
}

std::string ModuleManager::findFile(const std::string &fname, const std::vector<std::string> &load_path)
{
    for (const std::string &dir : load_path) {
        for (const std::string &candidate : {fname, fname + ".so"}) {
            const std::string path = dir + "/" + candidate;
            if (fileExist(path))
                return path;
        }
    }
    return {};
}

bool ModuleManager::fileExist(const std::string &filename)
{
    std::ifstream in(filename);
    return bool(in);
}

std::string ModuleManager::getInitFuncName(const std::string &file_path)
{
    std::string stem = coil::basename(file_path.c_str());
    const std::size_t dot = stem.find('.');
    if (dot != std::string::npos)
        stem.erase(dot);
    return m_initFuncPrefix + stem + m_initFuncSuffix;
}

} // namespace RTC

// --- RTC_impl::ExecutionContextProfile ---

namespace RTC_impl {

ExecutionContextProfile::ExecutionContextProfile(RTC::ExecutionKind kind)
    : rtclog("periodic_ecprofile")
    , m_period(std::chrono::nanoseconds(1000000))
{
    m_profile.kind = kind;
    m_profile.rate = 1000.0;
    m_profile.owner = RTC::RTObject::_nil();
    m_profile.participants.length(0);
    m_profile.properties.length(0);
}

ExecutionContextProfile::~ExecutionContextProfile() = default;

void ExecutionContextProfile::setObjRef(RTC::ExecutionContextService_ptr ec_ptr)
{
    std::lock_guard lock(m_profileMutex);
    m_ref = RTC::ExecutionContextService::_duplicate(ec_ptr);
}

RTC::ExecutionContextService_ptr ExecutionContextProfile::getObjRef() const
{
    std::lock_guard lock(m_profileMutex);
    return RTC::ExecutionContextService::_duplicate(m_ref);
}

RTC::ReturnCode_t ExecutionContextProfile::setRate(double rate)
{
    if (!(rate > 0.0))
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    m_profile.rate = rate;
    m_period = std::chrono::nanoseconds(static_cast<long long>(1e9 / rate));
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextProfile::setPeriod(std::chrono::nanoseconds period)
{
    if (period.count() <= 0)
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    m_period = period;
    m_profile.rate = 1e9 / double(period.count());
    return RTC::RTC_OK;
}

double ExecutionContextProfile::getRate() const
{
    std::lock_guard lock(m_profileMutex);
    return m_profile.rate;
}

std::chrono::nanoseconds ExecutionContextProfile::getPeriod() const
{
    std::lock_guard lock(m_profileMutex);
    return m_period;
}

const char *ExecutionContextProfile::getKindString(RTC::ExecutionKind kind)
{
    return RTC::ExecutionContextBase::getKindString(kind);
}

RTC::ReturnCode_t ExecutionContextProfile::setKind(RTC::ExecutionKind kind)
{
    if (kind < RTC::PERIODIC || kind > RTC::OTHER)
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    m_profile.kind = kind;
    return RTC::RTC_OK;
}

RTC::ExecutionKind ExecutionContextProfile::getKind() const
{
    std::lock_guard lock(m_profileMutex);
    return m_profile.kind;
}

RTC::ReturnCode_t ExecutionContextProfile::setOwner(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    RTC::RTObject_var rtobj = RTC::RTObject::_narrow(comp);
    if (CORBA::is_nil(rtobj))
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    m_profile.owner = rtobj._retn();
    return RTC::RTC_OK;
}

RTC::RTObject_ptr ExecutionContextProfile::getOwner() const
{
    std::lock_guard lock(m_profileMutex);
    return RTC::RTObject::_duplicate(m_profile.owner);
}

RTC::ReturnCode_t ExecutionContextProfile::addComponent(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    RTC::RTObject_var rtobj = RTC::RTObject::_narrow(comp);
    if (CORBA::is_nil(rtobj))
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    const CORBA::ULong n = m_profile.participants.length();
    m_profile.participants.length(n + 1);
    m_profile.participants[n] = rtobj._retn();
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextProfile::removeComponent(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    std::lock_guard lock(m_profileMutex);
    RTC::RTCList &list = m_profile.participants;
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (list[i]->_is_equivalent(comp)) {
            for (CORBA::ULong j = i + 1; j < list.length(); ++j)
                list[j - 1] = RTC::RTObject::_duplicate(list[j]);
            list.length(list.length() - 1);
            return RTC::RTC_OK;
        }
    }
    return RTC::BAD_PARAMETER;
}

const RTC::RTCList &ExecutionContextProfile::getComponentList() const
{
    return m_profile.participants;
}

void ExecutionContextProfile::setProperties(coil::Properties &props)
{
    std::lock_guard lock(m_profileMutex);
    for (const std::string &key : props.propertyNames()) {
        const CORBA::ULong n = m_profile.properties.length();
        bool replaced = false;
        for (CORBA::ULong i = 0; i < n && !replaced; ++i) {
            if (key == m_profile.properties[i].name.in()) {
                m_profile.properties[i].value <<= props.getProperty(key).c_str();
                replaced = true;
            }
        }
        if (!replaced) {
            m_profile.properties.length(n + 1);
            m_profile.properties[n].name = key.c_str();
            m_profile.properties[n].value <<= props.getProperty(key).c_str();
        }
    }
}

coil::Properties ExecutionContextProfile::getProperties() const
{
    std::lock_guard lock(m_profileMutex);
    coil::Properties props;
    for (CORBA::ULong i = 0; i < m_profile.properties.length(); ++i) {
        const char *value = nullptr;
        if (m_profile.properties[i].value >>= value)
            props.setProperty(m_profile.properties[i].name.in(), value);
    }
    return props;
}

RTC::ExecutionContextProfile *ExecutionContextProfile::getProfile()
{
    std::lock_guard lock(m_profileMutex);
    return new RTC::ExecutionContextProfile(m_profile);
}

const RTC::ExecutionContextProfile &ExecutionContextProfile::getProfile() const
{
    return m_profile;
}

void ExecutionContextProfile::lock() const
{
    m_profileMutex.lock();
}

void ExecutionContextProfile::unlock() const
{
    m_profileMutex.unlock();
}

} // namespace RTC_impl
