// SPDX-License-Identifier: MIT
// Loads component modules (shared libraries) and calls their init functions.
#ifndef RTC_MODULEMANAGER_H
#define RTC_MODULEMANAGER_H

#include <coil/DynamicLib.h>
#include <rtm/Manager.h>
#include <coil/Properties.h>
#include <rtm/ObjectManager.h>

#include <condition_variable>
#include <map>
#include <string>
#include <utility>
#include <vector>

#define CONFIG_EXT "manager.modules.config_ext"
#define CONFIG_PATH "manager.modules.config_path"
#define DETECT_MOD "manager.modules.detect_loadable"
#define MOD_LOADPTH "manager.modules.load_path"
#define INITFUNC_SFX "manager.modules.init_func_suffix"
#define INITFUNC_PFX "manager.modules.init_func_prefix"
#define ALLOW_ABSPATH "manager.modules.abs_path_allowed"
#define ALLOW_URL "manager.modules.download_allowed"
#define MOD_DWNDIR "manager.modules.download_dir"
#define MOD_DELMOD "manager.modules.download_cleanup"
#define MOD_PRELOAD "manager.modules.preload"

namespace RTC
{
/**
 * The modules of a process: finds a module file in `manager.modules.load_path` (an absolute
 * path only when `manager.modules.abs_path_allowed` is YES), opens it, calls its init function
 * with the process's RTC::Manager and keeps it open until unload(). Failures throw the nested
 * exception types, as OpenRTM-aist's does. Downloading modules from URLs is not supported:
 * such a name throws NotAllowedOperation.
 */
class ModuleManager
{
    using vProperties = std::vector<coil::Properties>;

public:
    explicit ModuleManager(coil::Properties &prop);
    ~ModuleManager();

    struct Error
    {
        explicit Error(std::string _reason)
            : reason(std::move(_reason))
        {
        }
        std::string reason;
    };
    struct NotFound
    {
        explicit NotFound(std::string _name)
            : name(std::move(_name))
        {
        }
        std::string name;
    };
    struct FileNotFound : public NotFound
    {
        explicit FileNotFound(const std::string &_name)
            : NotFound(_name)
        {
        }
    };
    struct ModuleNotFound : public NotFound
    {
        explicit ModuleNotFound(const std::string &_name)
            : NotFound(_name)
        {
        }
    };
    struct SymbolNotFound : public NotFound
    {
        explicit SymbolNotFound(const std::string &_name)
            : NotFound(_name)
        {
        }
    };
    struct NotAllowedOperation : public Error
    {
        explicit NotAllowedOperation(const std::string &_reason)
            : Error(_reason)
        {
        }
    };
    struct InvalidArguments : public Error
    {
        explicit InvalidArguments(const std::string &_reason)
            : Error(_reason)
        {
        }
    };
    struct InvalidOperation : public Error
    {
        explicit InvalidOperation(const std::string &_reason)
            : Error(_reason)
        {
        }
    };
    using ModuleInitFunc = void (*)(Manager *);

    /// Loads @p file_name; returns the path it was loaded from.
    std::string load(const std::string &file_name);
    /// Loads the module `module_file_path` (or `module_file_name`) of @p prop names.
    std::string load(coil::Properties &prop);
    /// Loads @p file_name and calls its @p init_func (none when empty).
    std::string load(const std::string &file_name, const std::string &init_func);
    std::string load(coil::Properties &prop, const std::string &init_func);
    void unload(const std::string &file_name);
    void unloadAll();
    /// The address of @p func_name in the loaded module @p file_name.
    void *symbol(const std::string &file_name, const std::string &func_name);
    void setLoadpath(const std::vector<std::string> &load_path);
    inline std::vector<std::string> getLoadPath() { return m_loadPath; }
    void addLoadpath(const std::vector<std::string> &load_path);
    /// One entry per loaded module: `file_path`.
    std::vector<coil::Properties> getLoadedModules();
    /// The module files in the load path: `module_file_name`, `module_file_path`.
    std::vector<coil::Properties> getLoadableModules();
    inline void allowAbsolutePath() { m_absoluteAllowed = true; }
    inline void disallowAbsolutePath() { m_absoluteAllowed = false; }
    inline void allowModuleDownload() { m_downloadAllowed = true; }
    inline void disallowModuleDownload() { m_downloadAllowed = false; }
    /// @p fname found in @p load_path (with or without the `.so` suffix); empty when not found.
    std::string findFile(const std::string &fname, const std::vector<std::string> &load_path);
    bool fileExist(const std::string &filename);
    /// `<prefix><file stem><suffix>`: `manager.modules.init_func_prefix` (none by default) and
    /// `manager.modules.init_func_suffix` (`Init` by default).
    std::string getInitFuncName(const std::string &file_path);

protected:
    struct DLLEntity
    {
        coil::Properties properties;
        coil::DynamicLib dll;
    };

    coil::Properties &m_properties;
    std::map<std::string, DLLEntity *> m_modules;
    std::vector<std::string> m_loadPath;
    std::vector<std::string> m_configPath;
    bool m_downloadAllowed;
    bool m_absoluteAllowed;
    std::string m_initFuncSuffix;
    std::string m_initFuncPrefix;
};
} // namespace RTC

#endif // RTC_MODULEMANAGER_H
