// SPDX-License-Identifier: MIT
#include "pycomponent.h"
#include "bindings.h"
#include "pycorbaport.h"
#include "pyinterpreter.h"
#include "pyinport.h"
#include "pyoutport.h"
#include "pyparameter.h"

#include <rtm/SystemLogger.h>

#include <algorithm>

namespace py = pybind11;

namespace RtPython {

namespace {

/// A callback's result: omniORBpy's ReturnCode_t items carry their value in _v; None counts as RTC_OK.
RTC::ReturnCode_t returnCode(const py::object &result)
{
    if (result.is_none())
        return RTC::RTC_OK;
    const py::object value = py::hasattr(result, "_v") ? result.attr("_v") : result;
    return py::isinstance<py::int_>(value) ? RTC::ReturnCode_t(value.cast<int>()) : RTC::RTC_ERROR;
}

} // namespace

PyComponent::PyComponent(RTC::Manager *manager)
    : DataFlowComponentBase(manager)
{
}

PyComponent *PyComponent::create(RTC::Manager *manager, const py::object &cls)
{
    Gil gil;
    auto *component = new PyComponent(manager);
    try {
        component->m_self = cls(py::cast(manager, py::return_value_policy::reference));
        component->m_self.attr("_rtc") = py::cast(component, py::return_value_policy::reference);
        component->findOwnCallbacks();
    } catch (py::error_already_set &error) {
        // The runtime needs a servant; this one refuses to initialize and says why.
        component->m_createError = traceback(error);
        component->m_self = py::object();
    }
    return component;
}

PyComponent::~PyComponent()
{
    finalizePorts();
    if (!interpreterAlive()) {
        m_self.release();
        for (py::object &port : m_ports)
            port.release();
        return;
    }
    Gil gil;
    if (m_self && py::hasattr(m_self, "_rtc"))
        m_self.attr("_rtc") = py::none();
    m_ports.clear();
    m_self = py::object();
}

void PyComponent::rememberListener(int kind, int type, pybind11::handle listener, void *made)
{
    m_madeListeners.push_back({kind, type, listener.ptr(), made});
}

void *PyComponent::takeListener(int kind, int type, pybind11::handle listener)
{
    auto it = std::find_if(m_madeListeners.begin(), m_madeListeners.end(), [&](const MadeListener &m) {
        return m.kind == kind && m.type == type && m.listener == listener.ptr();
    });
    if (it == m_madeListeners.end())
        return nullptr;
    void *made = it->made;
    m_madeListeners.erase(it);
    return made;
}

bool PyComponent::addPythonInPort(const std::string &name, py::object port)
{
    auto &inport = port.cast<PyInPort &>();
    m_ports.push_back(std::move(port));
    return addInPort(name.c_str(), inport);
}

bool PyComponent::addPythonOutPort(const std::string &name, py::object port)
{
    auto &outport = port.cast<PyOutPort &>();
    m_ports.push_back(std::move(port));
    return addOutPort(name.c_str(), outport);
}

bool PyComponent::addPythonPort(py::object port)
{
    if (py::isinstance<PyInPort>(port)) {
        const std::string name = port.cast<PyInPort &>().Runtime::PortBase::name();
        return addPythonInPort(name, std::move(port));
    }
    if (py::isinstance<PyOutPort>(port)) {
        const std::string name = port.cast<PyOutPort &>().Runtime::PortBase::name();
        return addPythonOutPort(name, std::move(port));
    }
    auto &service = port.cast<PyCorbaPort &>();
    m_ports.push_back(std::move(port));
    return addPort(static_cast<RTC::CorbaPort &>(service));
}

bool PyComponent::bindPythonParameter(const std::string &name, py::object variable, const std::string &defaultValue,
                                      py::object trans)
{
    if (trans.is_none() && !py::isinstance<py::list>(variable))
        throw py::type_error("bindParameter: the variable of " + name + " must be a list of one value, e.g. [0]");
    if (getConfigService().isExist(name.c_str()))
        return false;
    // Shared, not copied: the configuration copies its setters in threads that do not hold the GIL.
    auto parameter = std::make_shared<PyParameter>(std::move(variable), std::move(trans));
    if (!parameter->set(defaultValue))
        return false;
    // Without the interpreter, as every call into the configuration (configbindings.cpp).
    py::gil_scoped_release released;
    getConfigService().bindSetter(name.c_str(), defaultValue.c_str(),
                                  [parameter](const char *text) { return parameter->set(text); });
    // As OpenRTM-aist-Python's bindParameter: the variable takes the active set's value at once
    // (rtc.conf's `<category>.<type>.conf.default.<name>`), so onInitialize can use it.
    getConfigService().update(getConfigService().getActiveId(), name.c_str());
    return true;
}

void PyComponent::findOwnCallbacks()
{
    const py::object base = py::module_::import("OpenRTM_aist").attr("DataFlowComponentBase");
    const py::object cls = py::type::of(m_self);
    const py::dict own = m_self.attr("__dict__");
    for (const char *callback : {"onInitialize", "onFinalize", "onStartup", "onShutdown", "onActivated",
                                 "onDeactivated", "onAborting", "onError", "onReset", "onExecute", "onStateUpdate",
                                 "onRateChanged"}) {
        const bool inherited = py::hasattr(base, callback) && py::hasattr(cls, callback)
            && cls.attr(callback).is(base.attr(callback)) && !own.contains(callback);
        if (!inherited && py::hasattr(m_self, callback))
            m_ownCallbacks.insert(callback);
    }
}

template <typename... Arguments>
RTC::ReturnCode_t PyComponent::call(const char *callback, Arguments... arguments)
{
    if (!interpreterAlive() || !m_ownCallbacks.count(callback))
        return RTC::RTC_OK;
    Gil gil;
    if (!m_self || !py::hasattr(m_self, callback))
        return RTC::RTC_OK;
    try {
        return returnCode(m_self.attr(callback)(arguments...));
    } catch (py::error_already_set &error) {
        return fail(callback, error);
    }
}

RTC::ReturnCode_t PyComponent::fail(const char *callback, py::error_already_set &error)
{
    const std::string context = std::string(getInstanceName()) + ": " + callback
                                + "() raised an exception; the callback fails with RTC_ERROR:";
    RTC_ERROR_STR(context + "\n" + traceback(error));
    printError(context, error);
    return RTC::RTC_ERROR;
}

RTC::ReturnCode_t PyComponent::onInitialize()
{
    if (!m_createError.empty()) {
        RTC_ERROR_STR("the Python component could not be made:\n" + m_createError);
        setInitializeError("the Python component could not be made: " + m_createError);
        return RTC::RTC_ERROR;
    }
    return call("onInitialize");
}

RTC::ReturnCode_t PyComponent::onFinalize() { return call("onFinalize"); }
RTC::ReturnCode_t PyComponent::onStartup(RTC::UniqueId ec_id) { return call("onStartup", ec_id); }
RTC::ReturnCode_t PyComponent::onShutdown(RTC::UniqueId ec_id) { return call("onShutdown", ec_id); }
RTC::ReturnCode_t PyComponent::onActivated(RTC::UniqueId ec_id) { return call("onActivated", ec_id); }
RTC::ReturnCode_t PyComponent::onDeactivated(RTC::UniqueId ec_id) { return call("onDeactivated", ec_id); }
RTC::ReturnCode_t PyComponent::onAborting(RTC::UniqueId ec_id) { return call("onAborting", ec_id); }
RTC::ReturnCode_t PyComponent::onError(RTC::UniqueId ec_id) { return call("onError", ec_id); }
RTC::ReturnCode_t PyComponent::onReset(RTC::UniqueId ec_id) { return call("onReset", ec_id); }
RTC::ReturnCode_t PyComponent::onExecute(RTC::UniqueId ec_id) { return call("onExecute", ec_id); }
RTC::ReturnCode_t PyComponent::onStateUpdate(RTC::UniqueId ec_id) { return call("onStateUpdate", ec_id); }
RTC::ReturnCode_t PyComponent::onRateChanged(RTC::UniqueId ec_id) { return call("onRateChanged", ec_id); }

void bindComponent(py::module_ &module)
{
    // OpenRTM-aist-Python's Logger methods: RTC_ERROR(msg, opt) writes msg % opt (msg when opt is
    // empty) when the level is on.
    py::class_<RTC::Logger, std::unique_ptr<RTC::Logger, py::nodelete>> logger(module, "Logger");
    const std::pair<const char *, int> levels[] = {
        {"RTC_FATAL", RTC::Logger::RTL_FATAL}, {"RTC_ERROR", RTC::Logger::RTL_ERROR},
        {"RTC_WARN", RTC::Logger::RTL_WARN},   {"RTC_INFO", RTC::Logger::RTL_INFO},
        {"RTC_DEBUG", RTC::Logger::RTL_DEBUG}, {"RTC_TRACE", RTC::Logger::RTL_TRACE},
        {"RTC_VERBOSE", RTC::Logger::RTL_VERBOSE}, {"RTC_PARANOID", RTC::Logger::RTL_PARANOID}};
    for (const auto &[name, level] : levels) {
        logger.def(
            name,
            [level = level](RTC::Logger &log, const py::object &message, const py::object &arguments) {
                if (!log.isValid(level))
                    return;
                const std::string text = py::str(py::bool_(arguments) ? message.attr("__mod__")(arguments) : message);
                py::gil_scoped_release released;
                log.lock();
                log.level(level) << text << std::endl;
                log.unlock();
            },
            py::arg("msg"), py::arg("opt") = py::none());
    }
    logger.def("isValid", &RTC::Logger::isValid, py::arg("level"));

    // Never deleted from Python: the ORB owns the bridge.
    py::class_<PyComponent, std::unique_ptr<PyComponent, py::nodelete>>(module, "Component")
        .def("addInPort", &PyComponent::addPythonInPort, py::arg("name"), py::arg("inport"))
        .def("addOutPort", &PyComponent::addPythonOutPort, py::arg("name"), py::arg("outport"))
        .def("addPort", &PyComponent::addPythonPort, py::arg("port"))
        .def("bindParameter", &PyComponent::bindPythonParameter, py::arg("param_name"), py::arg("var"),
             py::arg("def_val"), py::arg("trans") = py::none())
        .def("updateParameters", &PyComponent::updateParameters, py::arg("config_set"),
             py::call_guard<py::gil_scoped_release>()) // see WithoutGil in configbindings.cpp
        .def("getInstanceName", &PyComponent::getInstanceName)
        .def("getTypeName", &PyComponent::getTypeName)
        .def("getCategory", &PyComponent::getCategory)
        .def("getProperties", &PyComponent::getProperties, py::return_value_policy::reference_internal)
        .def_property_readonly("_rtcout", &PyComponent::logger, py::return_value_policy::reference_internal);
}

} // namespace RtPython
