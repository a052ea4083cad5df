// SPDX-License-Identifier: MIT
#pragma once

#include <mutex>
#include <string>

namespace Runtime {

/**
 * Loads component modules written in Python (`<Name>.py` with `<Name>Init(manager)`) into this
 * process through a plugin library that embeds the interpreter (python/, built when Python's and
 * pybind11's development files are there). The plugin is opened on the first `.py` load, so a
 * manager needs no Python installed until it loads a Python module; without the plugin such a
 * load is refused with the reason.
 *
 * The plugin exports `rtstudioLoadPythonModule`, see PluginEntry.
 */
class PythonModuleLoader
{
public:
    /**
     * The plugin's entry: runs module file @p path (as `import` would) and calls its function
     * @p initFunction with the process's manager; false with @p error naming the file and line
     * when the module or its init function raises.
     */
    using PluginEntry = bool (*)(const char *path, const char *initFunction, std::string *error);

    /// Whether @p path names a Python module (by its suffix).
    static bool isPythonModule(const std::string &path);
    /**
     * The plugin of this runtime: `rtstudio/librtstudio_pymodules.so` beside the library (or
     * program) the runtime is part of.
     */
    static std::string defaultPlugin();

    /**
     * Loads module @p path, calling its @p initFunction, through the plugin at @p plugin (opened
     * once; later calls use the one opened first). False with @p error when the plugin cannot be
     * opened or the module does not load.
     */
    bool load(const std::string &plugin, const std::string &path, const std::string &initFunction, std::string *error);

private:
    PluginEntry entry(const std::string &plugin, std::string *error);

    std::mutex m_mutex;
    PluginEntry m_entry = nullptr;
};

} // namespace Runtime
