// SPDX-License-Identifier: MIT
// OpenRTM_aist.Manager: the SDK's manager, with Python module init procedures and component classes.
#include "bindings.h"
#include "pycomponent.h"
#include "pyinterpreter.h"

#include <rtm/Manager.h>
#include <rtmruntime/manager.h>

#include <pybind11/stl.h>

#include <unistd.h>

namespace py = pybind11;

namespace RtPython {

namespace {

// One manager per process, so one init procedure; never destroyed (static destructors run after
// the interpreter is gone).
py::object *moduleInitProc = nullptr;

void callModuleInitProc(RTC::Manager *manager)
{
    Gil gil;
    if (moduleInitProc == nullptr)
        return;
    try {
        (*moduleInitProc)(py::cast(manager, py::return_value_policy::reference));
    } catch (py::error_already_set &error) {
        printError("the module init procedure raised an exception:", error);
    }
}

RTC::Manager *initManager(const std::vector<std::string> &arguments)
{
    // The manager may keep argv; these copies live as long as the process.
    static std::vector<std::string> kept;
    static std::vector<char *> argv;
    kept = arguments;
    argv.clear();
    for (std::string &argument : kept)
        argv.push_back(argument.data());
    argv.push_back(nullptr);
    return RTC::Manager::init(int(kept.size()), argv.data());
}

Runtime::Properties toRuntime(const coil::Properties &properties)
{
    Runtime::Properties result;
    for (const std::string &key : properties.propertyNames())
        result.set(key, properties.getProperty(key));
    return result;
}

/**
 * Registers the Python component class @p cls under @p profile. The class is held through a
 * shared pointer whose last owner drops it with the GIL: the runtime copies factories in threads
 * that do not hold the GIL, and copying a py::object there would race on its reference count.
 */
bool registerFactory(RTC::Manager &manager, const coil::Properties &profile, py::object cls)
{
    if (profile.getProperty("implementation_id").empty())
        return false;
    std::shared_ptr<py::object> held(new py::object(std::move(cls)), [](py::object *object) {
        if (interpreterAlive()) {
            Gil gil;
            delete object;
        }
    });
    Runtime::ComponentFactory factory;
    factory.profile = toRuntime(profile);
    factory.create = [&manager, held](PortableServer::POA_ptr) -> Runtime::RtObject * {
        return PyComponent::create(&manager, *held);
    };
    manager.runtime()->registerFactory(std::move(factory));
    return true;
}

/// The Python object of the component createComponent() made; None when it failed or is not Python.
py::object createComponent(RTC::Manager &manager, const std::string &arguments)
{
    RTC::RTObject_impl *component = nullptr;
    {
        py::gil_scoped_release released;
        component = manager.createComponent(arguments.c_str());
    }
    auto *python = dynamic_cast<PyComponent *>(component);
    return python ? python->pythonObject() : py::none();
}

/**
 * OpenRTM-aist-Python's shutdown(): the program's main thread (the script, which ends next) waits
 * until the manager has stopped, as there; the runtime would otherwise still be stopping the ORB
 * while the process exits. A component's thread only starts it.
 */
void shutdownManager(RTC::Manager &manager)
{
    manager.shutdown();
    if (gettid() == getpid())
        manager.join();
}

} // namespace

void bindManager(py::module_ &module)
{
    using Release = py::call_guard<py::gil_scoped_release>;
    py::class_<RTC::Manager, std::unique_ptr<RTC::Manager, py::nodelete>>(module, "Manager")
        .def_static("init", &initManager, py::arg("argv"), py::return_value_policy::reference, Release())
        // The older form, Manager.init(len(sys.argv), sys.argv): the count adds nothing.
        .def_static(
            "init", [](int, const std::vector<std::string> &arguments) { return initManager(arguments); },
            py::arg("argc"), py::arg("argv"), py::return_value_policy::reference, Release())
        .def_static("instance", &RTC::Manager::instance, py::return_value_policy::reference)
        .def("setModuleInitProc", [](RTC::Manager &manager, py::object proc) {
            if (moduleInitProc == nullptr)
                moduleInitProc = new py::object;
            *moduleInitProc = std::move(proc);
            manager.setModuleInitProc(&callModuleInitProc);
        }, py::arg("proc"))
        .def("activateManager", &RTC::Manager::activateManager, Release())
        .def("runManager", &RTC::Manager::runManager, py::arg("no_block") = false, Release())
        .def("registerFactory", [](RTC::Manager &manager, const coil::Properties &profile, py::object cls,
                                   py::object) { return registerFactory(manager, profile, std::move(cls)); },
             py::arg("profile"), py::arg("new_func"), py::arg("delete_func") = py::none())
        .def("createComponent", &createComponent, py::arg("comp_args"))
        .def("getConfig", &RTC::Manager::getConfig, py::return_value_policy::reference)
        .def("shutdown", &shutdownManager, Release())
        .def("join", &RTC::Manager::join, Release());
}

} // namespace RtPython
