// SPDX-License-Identifier: MIT
// Loadable modules: OpenRTM-aist component modules whose init function (`extern "C" void
// <Name>Init(RTC::Manager *)`) registers component factories; the component SDK calls it. Python
// modules (`<Name>.py`, `def <Name>Init(manager)`) run in this process too, see PythonModuleLoader.
#include "managerdetail.h"
#include "tlsarguments.h"

#include <algorithm>
#include <iostream>
#include <dirent.h>
#include <dlfcn.h>
#include <sys/stat.h>

namespace Runtime {

namespace {

bool isFile(const std::string &path)
{
    struct stat info{};
    return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::string baseName(const std::string &path)
{
    std::string name = path.substr(path.rfind('/') + 1);
    const size_t dot = name.find('.');
    if (dot != std::string::npos)
        name = name.substr(0, dot);
    if (name.compare(0, 3, "lib") == 0 && name.size() > 3 && !PythonModuleLoader::isPythonModule(path))
        name = name.substr(3);
    return name;
}

bool isDirectory(const std::string &path)
{
    struct stat info{};
    return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

/// The module a thread is loading: the factories its init function registers come from it.
thread_local std::string loadingModule;

/// The folder of every component package (rtctl package) below manager.modules.package_path.
std::vector<std::string> packageDirs(const Properties &config)
{
    std::vector<std::string> result;
    for (const std::string &root : split(config.value("manager.modules.package_path", RTSTUDIO_COMPONENT_PACKAGES_DIR), ',')) {
        DIR *d = opendir(root.c_str());
        if (!d)
            continue;
        std::vector<std::string> packages;
        while (dirent *entry = readdir(d)) {
            const std::string name = entry->d_name;
            if (name.front() != '.' && isDirectory(root + '/' + name))
                packages.push_back(root + '/' + name);
        }
        closedir(d);
        std::sort(packages.begin(), packages.end());
        result.insert(result.end(), packages.begin(), packages.end());
    }
    return result;
}

/// The folders modules are looked for in: manager.modules.load_path, then those of the packages
/// in the manager's package store (@p installed), then the folder of every component package
/// (rtctl package) below manager.modules.package_path, by package name.
std::vector<std::string> moduleDirs(const Properties &config, const std::vector<std::string> &installed)
{
    std::vector<std::string> dirs = split(config.value("manager.modules.load_path", "."), ',');
    dirs.insert(dirs.end(), installed.begin(), installed.end());
    const std::vector<std::string> packages = packageDirs(config);
    dirs.insert(dirs.end(), packages.begin(), packages.end());
    return dirs;
}

/// The language of module file @p path, as factory profiles name it.
std::string moduleLanguage(const std::string &path)
{
    return PythonModuleLoader::isPythonModule(path) ? "Python" : "C++";
}

} // namespace

std::vector<std::string> Manager::installedPackages() const
{
    // A package's module folder is named after the package, in the store as below package_path.
    std::vector<std::string> dirs = installedModuleDirs(std::string());
    const std::vector<std::string> system = packageDirs(m_config);
    dirs.insert(dirs.end(), system.begin(), system.end());
    std::vector<std::string> names;
    for (const std::string &dir : dirs)
        names.push_back(dir.substr(dir.rfind('/') + 1));
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

std::string moduleBeingLoaded()
{
    return loadingModule;
}

std::string moduleInDirs(const std::string &type, const std::vector<std::string> &dirs)
{
    for (const std::string &dir : dirs) {
        for (const char *suffix : {".so", ".py"}) {
            if (isFile(dir + '/' + type + suffix))
                return dir + '/' + type + suffix;
        }
    }
    return {};
}

void Manager::setPackageModuleDirs(PackageModuleDirs dirs)
{
    m_packageModuleDirs = std::move(dirs);
}

std::vector<std::string> Manager::installedModuleDirs(const std::string &version) const
{
    return m_packageModuleDirs ? m_packageModuleDirs(version) : std::vector<std::string>();
}

std::vector<std::string> Manager::runningModulePaths()
{
    std::lock_guard lock(m_mutex);
    std::vector<std::string> paths;
    for (const auto &component : m_components) {
        if (!component->modulePath.empty())
            paths.push_back(component->modulePath);
    }
    return paths;
}

std::optional<ComponentFactory> Manager::factoryOfModule(const CreateRequest &request, const std::string &module)
{
    const auto find = [this, &request, &module]() -> std::optional<ComponentFactory> {
        std::lock_guard lock(m_mutex);
        for (const ComponentFactory &factory : m_factories) {
            if (factory.modulePath == module && factory.implementationId() == request.implementationId)
                return factory;
        }
        return std::nullopt;
    };
    if (std::optional<ComponentFactory> factory = find())
        return factory;
    if (!loadRequestedModule(module, std::string(), nullptr))
        return std::nullopt;
    return find();
}

std::string Manager::findModuleFile(const std::string &requested) const
{
    if (requested.empty())
        return {};
    // Relative names are looked up in manager.modules.load_path and the installed component
    // packages' folders, with or without ".so" (or ".py").
    std::vector<std::string> candidates;
    const std::vector<std::string> dirs = moduleDirs(m_config, installedModuleDirs(std::string()));
    for (const std::string &name : {requested, requested + ".so", requested + ".py"}) {
        if (name.front() == '/')
            candidates.push_back(name);
        for (const std::string &dir : dirs)
            candidates.push_back(dir + '/' + name);
    }
    auto found = std::find_if(candidates.begin(), candidates.end(), isFile);
    return found == candidates.end() ? std::string() : *found;
}

void Manager::setModuleProfileProgram(const std::string &program)
{
    m_moduleProfiler.setProgram(program);
}

void Manager::setModuleInitCall(ModuleInitCall call)
{
    m_moduleInitCall = std::move(call);
}

bool Manager::loadModule(const std::string &requested, const std::string &initFunction, std::string *error)
{
    if (requested.empty())
        return fail("load_module: no module path given", error);
    if (!m_moduleInitCall)
        return fail("load_module: this manager has no component SDK to run module init functions", error);
    const std::string path = findModuleFile(requested);
    if (path.empty())
        return fail("load_module: no module file '" + requested + "'", error);
    bool loaded = false;
    {
        std::lock_guard lock(m_mutex);
        for (const auto &module : m_modules)
            loaded = loaded || module->path == path;
    }
    if (loaded)
        return fail("load_module: '" + path + "' is already loaded", error);
    const std::string function = initFunction.empty() ? baseName(path) + "Init" : initFunction;
    void *handle = nullptr;
    loadingModule = path;
    const bool initialized = PythonModuleLoader::isPythonModule(path) ? runPythonModule(path, function, error)
                                                                       : runSharedModule(path, function, &handle, error);
    loadingModule.clear();
    if (!initialized)
        return false;
    std::lock_guard lock(m_mutex);
    m_modules.push_back(std::make_unique<Module>(Module{path, function, handle}));
    return true;
}

bool Manager::loadRequestedModule(const std::string &requested, const std::string &initFunction, std::string *error)
{
    const std::string path = findModuleFile(requested);
    if (!path.empty() && !m_config.isYes("manager.modules.abs_path_allowed") && !inModuleFolder(path)) {
        return fail("load_module: '" + path
                        + "' is outside the manager's module folders (manager.modules.load_path, its package store) "
                          "and manager.modules.abs_path_allowed is NO",
                    error);
    }
    return loadModule(requested, initFunction, error);
}

bool Manager::inModuleFolder(const std::string &path) const
{
    // Compared as the file system resolves them, so that neither `..` nor a link leads out.
    const auto resolved = [](const std::string &name) {
        char *real = realpath(name.c_str(), nullptr);
        const std::string result = real ? real : "";
        free(real);
        return result;
    };
    const std::string folder = resolved(path.substr(0, path.rfind('/') + 1));
    if (folder.empty())
        return false;
    const std::vector<std::string> dirs = moduleDirs(m_config, installedModuleDirs(std::string()));
    return std::any_of(dirs.begin(), dirs.end(), [&](const std::string &dir) { return resolved(dir) == folder; });
}

bool Manager::runSharedModule(const std::string &path, const std::string &function, void **handle, std::string *error)
{
    *handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!*handle)
        return fail(std::string("load_module: '") + path + "' is not a loadable module: " + dlerror(), error);
    void *init = dlsym(*handle, function.c_str());
    if (!init) {
        dlclose(*handle);
        return fail("load_module: '" + path + "' has no init function '" + function + "'", error);
    }
    m_moduleInitCall(init);
    return true;
}

bool Manager::runPythonModule(const std::string &path, const std::string &function, std::string *error)
{
    // manager.modules.Python.plugin: another build of the plugin (tests use a missing one).
    const std::string plugin = m_config.value("manager.modules.Python.plugin", PythonModuleLoader::defaultPlugin());
    std::string why;
    if (m_pythonModules.load(plugin, path, function, &why))
        return true;
    // An init function that raised halfway may have registered types of a module that is not loaded.
    {
        std::lock_guard lock(m_mutex);
        dropFactoriesOf(path);
    }
    return fail("load_module: " + why, error);
}

void Manager::preloadModules()
{
    for (const char *key : {"manager.modules.preload", "manager.preload.modules"}) {
        for (const std::string &module : split(m_config.value(key), ',')) {
            const size_t colon = module.find(':');
            const std::string name = module.substr(0, colon);
            // An rtc.conf shared with OpenRTM-aist preloads its TLS module, a library of OpenRTM-aist's
            // own: here TLS is part of the runtime and follows the same corba.ssl.* keys.
            if (baseName(name) == "SSLTransport") {
                std::cerr << programName() << ": " << name << " (OpenRTM-aist's TLS module) is not loaded: TLS is "
                          << (tlsSettings().enabled() ? "on" : "off") << " by the corba.ssl.* keys" << std::endl;
                continue;
            }
            loadModule(name, colon == std::string::npos ? "" : module.substr(colon + 1), nullptr);
        }
    }
}

void Manager::precreateComponents()
{
    for (const std::string &request : split(m_config.value("manager.components.precreate"), ','))
        CORBA::release(createComponent(request, nullptr));
}

bool Manager::unloadModule(const std::string &path, std::string *error)
{
    std::lock_guard lock(m_mutex);
    auto it = std::find_if(m_modules.begin(), m_modules.end(), [&path](const auto &m) {
        return m->path == path || baseName(m->path) == baseName(path);
    });
    if (it == m_modules.end()) {
        m_lastError = "unload_module: '" + path + "' is not loaded";
        if (error)
            *error = m_lastError;
        return false;
    }
    // Components made from the module may still run its code: the library stays mapped, but
    // its types can no longer be created and it is no longer listed.
    dropFactoriesOf((*it)->path);
    m_modules.erase(it);
    return true;
}

void Manager::dropFactoriesOf(const std::string &modulePath)
{
    m_factories.erase(std::remove_if(m_factories.begin(), m_factories.end(),
                                     [&modulePath](const ComponentFactory &f) { return f.modulePath == modulePath; }),
                      m_factories.end());
}

std::vector<Properties> Manager::loadableModules()
{
    const Properties config = configuration();
    std::vector<std::string> files;
    for (const std::string &dir : moduleDirs(config, installedModuleDirs(std::string()))) {
        DIR *d = opendir(dir.c_str());
        if (!d)
            continue;
        while (dirent *entry = readdir(d)) {
            const std::string name = entry->d_name;
            if ((name.size() >= 4 && name.compare(name.size() - 3, 3, ".so") == 0)
                || PythonModuleLoader::isPythonModule(name))
                files.push_back(dir + '/' + name);
        }
        closedir(d);
    }
    std::sort(files.begin(), files.end());
    // As OpenRTM-aist's: one entry per component type a module registers, its factory profile with
    // the module's file; a library that holds no component is not listed. A process that cannot
    // profile modules names each file once.
    std::vector<std::vector<Properties>> profiles;
    if (m_moduleProfiler.hasProgram()) {
        profiles = m_moduleProfiler.profiles(files, int(configNumber("manager.modules.profile_timeout", 5000)));
    } else {
        for (const std::string &file : files) {
            Properties unprofiled;
            unprofiled.set("language", moduleLanguage(file));
            profiles.push_back({unprofiled});
        }
    }
    std::vector<Properties> result;
    for (std::size_t i = 0; i < files.size(); ++i) {
        for (Properties module : profiles[i]) {
            module.set("module_file_name", files[i].substr(files[i].rfind('/') + 1));
            module.set("module_file_path", files[i]);
            result.push_back(std::move(module));
        }
    }
    return result;
}

std::vector<Properties> Manager::loadedModules()
{
    std::lock_guard lock(m_mutex);
    std::vector<Properties> result;
    for (const auto &module : m_modules) {
        Properties p;
        p.set("file_path", module->path);
        p.set("module_file_path", module->path);
        p.set("init_function", module->initFunction);
        p.set("language", moduleLanguage(module->path));
        result.push_back(p);
    }
    return result;
}

std::vector<Properties> Manager::factoryProfiles()
{
    std::lock_guard lock(m_mutex);
    std::vector<Properties> result;
    for (const ComponentFactory &factory : m_factories) {
        Properties p = factory.profile;
        if (!factory.modulePath.empty())
            p.set("module_file_path", factory.modulePath);
        result.push_back(p);
    }
    return result;
}

} // namespace Runtime
