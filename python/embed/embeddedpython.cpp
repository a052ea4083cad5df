// SPDX-License-Identifier: MIT
#include "embeddedpython.h"

#include <pybind11/embed.h>

#include <dlfcn.h>
#include <iostream>

namespace py = pybind11;

namespace RtPython {

EmbeddedPython &EmbeddedPython::instance()
{
    // Never destroyed: static destructors run while the execution contexts may still call Python.
    static EmbeddedPython *python = new EmbeddedPython;
    return *python;
}

EmbeddedPython::EmbeddedPython()
{
    // A Python program that loads a module through its manager has its interpreter already.
    if (Py_IsInitialized())
        return;
    const char *const argv[] = {"rtmanager"};
    py::initialize_interpreter(false, 1, argv, false);
    {
        const py::module_ sys = py::module_::import("sys");
        sys.attr("path").attr("insert")(0, packagesDir());
        // What components print reaches the manager's output line by line, as a C++ component's
        // std::endl does, not when a buffer fills.
        for (const char *stream : {"stdout", "stderr"}) {
            const py::object file = sys.attr(stream);
            if (!file.is_none() && py::hasattr(file, "reconfigure"))
                file.attr("reconfigure")(py::arg("line_buffering") = true);
        }
    }
    // Kept for ever: the starting thread gives the GIL away and never takes it back this way.
    PyEval_SaveThread();
}

std::string EmbeddedPython::packagesDir()
{
    // <prefix>/lib/rtstudio/librtstudio_pymodules.so, the packages in <prefix>/lib/python3/dist-packages.
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&EmbeddedPython::packagesDir), &info) == 0 || !info.dli_fname)
        return {};
    const std::string self = info.dli_fname;
    return self.substr(0, self.rfind('/')) + "/../python3/dist-packages";
}

py::module_ EmbeddedPython::runModuleFile(const std::string &path)
{
    const std::string folder = path.substr(0, path.rfind('/'));
    const py::module_ sys = py::module_::import("sys");
    const py::list searchPath = sys.attr("path");
    if (!searchPath.contains(folder))
        searchPath.attr("insert")(0, folder);
    std::string name = path.substr(path.rfind('/') + 1);
    name = name.substr(0, name.size() - 3);
    const py::module_ util = py::module_::import("importlib.util");
    const py::object spec = util.attr("spec_from_file_location")(name, path);
    py::module_ module = util.attr("module_from_spec")(spec);
    const py::dict modules = sys.attr("modules");
    modules[py::str(name)] = module;
    try {
        spec.attr("loader").attr("exec_module")(module);
    } catch (py::error_already_set &) {
        modules.attr("pop")(name, py::none());
        throw;
    }
    return module;
}

std::string EmbeddedPython::location(const std::string &path, py::error_already_set &error)
{
    // A syntax error is where the compiler stopped, which no frame shows.
    if (error.matches(PyExc_SyntaxError)) {
        return py::str(error.value().attr("filename")).cast<std::string>() + ':'
            + py::str(error.value().attr("lineno")).cast<std::string>();
    }
    // The innermost line of the module's own file, else the innermost line of all.
    std::string where, innermost;
    for (const py::handle frame : py::module_::import("traceback").attr("extract_tb")(error.trace())) {
        const std::string file = frame.attr("filename").cast<std::string>();
        innermost = file + ':' + py::str(frame.attr("lineno")).cast<std::string>();
        if (file == path)
            where = innermost;
    }
    return where.empty() ? innermost : where;
}

std::string EmbeddedPython::describe(const std::string &path, py::error_already_set &error)
{
    const py::list what = py::module_::import("traceback").attr("format_exception_only")(error.type(), error.value());
    const std::string where = location(path, error);
    std::string message = py::str(what[py::len(what) - 1]).cast<std::string>();
    while (!message.empty() && message.back() == '\n')
        message.pop_back();
    return "'" + path + "' does not load: " + (where.empty() ? std::string() : where + ": ") + message;
}

bool EmbeddedPython::loadModule(const std::string &requested, const std::string &initFunction, std::string *error)
{
    py::gil_scoped_acquire gil;
    std::string path = requested;
    try {
        // Tracebacks name the file as it was run: absolute, as the manager's messages do.
        path = py::module_::import("os.path").attr("abspath")(requested).cast<std::string>();
        const py::module_ module = runModuleFile(path);
        if (!py::hasattr(module, initFunction.c_str())) {
            *error = "'" + path + "' has no init function '" + initFunction + "'";
            return false;
        }
        const py::object manager = py::module_::import("OpenRTM_aist").attr("Manager").attr("instance")();
        module.attr(initFunction.c_str())(manager);
        return true;
    } catch (py::error_already_set &raised) {
        *error = describe(path, raised);
        // Not PyErr_Print(), which would end the process on a SystemExit.
        py::module_::import("traceback").attr("print_exception")(raised.type(), raised.value(), raised.trace());
        return false;
    } catch (const std::exception &failure) {
        *error = "'" + path + "' does not load: " + failure.what();
        return false;
    }
}

} // namespace RtPython

/// The plugin's entry for Runtime::PythonModuleLoader (see PythonModuleLoader::PluginEntry).
extern "C" __attribute__((visibility("default"))) bool rtstudioLoadPythonModule(const char *path,
                                                                                const char *initFunction,
                                                                                std::string *error)
{
    return RtPython::EmbeddedPython::instance().loadModule(path, initFunction, error);
}
