// SPDX-License-Identifier: MIT
#include "pythonmoduleloader.h"

#include <dlfcn.h>

namespace Runtime {

bool PythonModuleLoader::isPythonModule(const std::string &path)
{
    static const std::string suffix = ".py";
    return path.size() > suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string PythonModuleLoader::defaultPlugin()
{
    // Installed as in the build tree: <prefix>/lib/librtstudio_rtm.so and <prefix>/lib/rtstudio/.
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&PythonModuleLoader::defaultPlugin), &info) == 0 || !info.dli_fname)
        return "rtstudio/librtstudio_pymodules.so";
    const std::string self = info.dli_fname;
    return self.substr(0, self.rfind('/') + 1) + "rtstudio/librtstudio_pymodules.so";
}

PythonModuleLoader::PluginEntry PythonModuleLoader::entry(const std::string &plugin, std::string *error)
{
    std::lock_guard lock(m_mutex);
    if (m_entry)
        return m_entry;
    // Global: the extension modules the interpreter loads later (ours and the standard library's)
    // take Python's symbols from the libpython the plugin brings.
    void *handle = dlopen(plugin.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
        *error = std::string("Python modules need the Python support of RT Studio's SDK (python3 and ") + plugin
                 + "): " + dlerror();
        return nullptr;
    }
    // Never closed: the interpreter it started lives as long as the process.
    m_entry = reinterpret_cast<PluginEntry>(dlsym(handle, "rtstudioLoadPythonModule"));
    if (!m_entry)
        *error = "'" + plugin + "' is not RT Studio's Python plugin (no rtstudioLoadPythonModule)";
    return m_entry;
}

bool PythonModuleLoader::load(const std::string &plugin, const std::string &path, const std::string &initFunction,
                              std::string *error)
{
    const PluginEntry load = entry(plugin, error);
    return load && load(path.c_str(), initFunction.c_str(), error);
}

} // namespace Runtime
