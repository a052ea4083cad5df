// SPDX-License-Identifier: MIT
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * The Python interpreter of a process that embeds it to run Python component modules beside its
 * C++ components (rtmanager, through the plugin librtstudio_pymodules). Started on first use with
 * RT Studio's packages (OpenRTM_aist, RTC) first on its path and without signal handlers (the
 * manager takes its signals itself); the starting thread then gives up the GIL, which every
 * caller, the execution contexts' threads among them, takes for as long as it runs Python. The
 * interpreter is never finalized: components may run Python until the process ends.
 */
class EmbeddedPython
{
public:
    /// The process's interpreter, started on the first call.
    static EmbeddedPython &instance();

    /**
     * Runs module file @p requested as `import` would (its folder put first on the path, so that it
     * finds the modules beside it) and calls its function @p initFunction with the process's
     * OpenRTM_aist.Manager. False with @p error when the module or the function raises: where
     * (`file:line`, the innermost line of the module's own file when there is one) and what;
     * the traceback goes to standard error.
     */
    bool loadModule(const std::string &requested, const std::string &initFunction, std::string *error);

private:
    EmbeddedPython();

    /// The folder holding RT Studio's packages, from where this plugin lies.
    static std::string packagesDir();
    static pybind11::module_ runModuleFile(const std::string &path);
    /// `file:line` where @p error arose, preferring the module @p path's own lines.
    static std::string location(const std::string &path, pybind11::error_already_set &error);
    /// What the manager says of a module @p path that raised @p error.
    static std::string describe(const std::string &path, pybind11::error_already_set &error);
};

} // namespace RtPython
