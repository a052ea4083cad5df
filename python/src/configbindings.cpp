// SPDX-License-Identifier: MIT
// Configuration from Python as OpenRTM-aist-Python names it: the component's configuration sets
// (`self._configsets`) and the configuration listeners with their types.
#include "bindings.h"
#include "pycomponent.h"
#include "pyconfigurationlisteners.h"

#include <rtm/ConfigAdmin.h>

#include <pybind11/stl.h>

#include <optional>

namespace py = pybind11;

namespace RtPython {

namespace {

using ComponentClass = py::class_<PyComponent, std::unique_ptr<PyComponent, py::nodelete>>;

void bindListenerTypes(py::module_ &module)
{
    py::enum_<RTC::ConfigurationParamListenerType>(module, "ConfigurationParamListenerType")
        .value("ON_UPDATE_CONFIG_PARAM", RTC::ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM);
    py::enum_<RTC::ConfigurationSetListenerType>(module, "ConfigurationSetListenerType")
        .value("ON_SET_CONFIG_SET", RTC::ConfigurationSetListenerType::ON_SET_CONFIG_SET)
        .value("ON_ADD_CONFIG_SET", RTC::ConfigurationSetListenerType::ON_ADD_CONFIG_SET);
    py::enum_<RTC::ConfigurationSetNameListenerType>(module, "ConfigurationSetNameListenerType")
        .value("ON_UPDATE_CONFIG_SET", RTC::ConfigurationSetNameListenerType::ON_UPDATE_CONFIG_SET)
        .value("ON_REMOVE_CONFIG_SET", RTC::ConfigurationSetNameListenerType::ON_REMOVE_CONFIG_SET)
        .value("ON_ACTIVATE_CONFIG_SET", RTC::ConfigurationSetNameListenerType::ON_ACTIVATE_CONFIG_SET);
}

/// Copies, so that Python never holds a set the configuration may drop.
std::vector<coil::Properties> configurationSets(RTC::ConfigAdmin &admin)
{
    std::vector<coil::Properties> sets;
    for (const coil::Properties *set : admin.getConfigurationSets())
        sets.push_back(*set);
    return sets;
}

/// Calls into the configuration are made without the interpreter: the configuration tells its
/// listeners, which take the interpreter, while it holds its lock, so a thread that waits for that
/// lock (the execution context asking for the active set) must not hold the interpreter meanwhile.
using WithoutGil = py::call_guard<py::gil_scoped_release>;

void bindConfigAdmin(py::module_ &module)
{
    py::class_<RTC::ConfigAdmin, std::unique_ptr<RTC::ConfigAdmin, py::nodelete>>(module, "ConfigAdmin")
        .def("getActiveId", [](RTC::ConfigAdmin &admin) { return std::string(admin.getActiveId()); }, WithoutGil())
        .def("haveConfig", &RTC::ConfigAdmin::haveConfig, py::arg("config_id"), WithoutGil())
        .def("isActive", &RTC::ConfigAdmin::isActive, WithoutGil())
        .def("isChanged", &RTC::ConfigAdmin::isChanged, WithoutGil())
        .def("isExist", &RTC::ConfigAdmin::isExist, py::arg("param_name"), WithoutGil())
        .def("changedParameters", [](RTC::ConfigAdmin &admin) { return coil::vstring(admin.changedParameters()); },
             WithoutGil())
        .def("getConfigurationSets", &configurationSets, WithoutGil())
        .def("getConfigurationSet", [](RTC::ConfigAdmin &admin, const std::string &id) {
            return coil::Properties(admin.getConfigurationSet(id.c_str()));
        }, py::arg("config_id"), WithoutGil())
        .def("getActiveConfigurationSet", [](RTC::ConfigAdmin &admin) {
            return coil::Properties(admin.getActiveConfigurationSet());
        }, WithoutGil())
        .def("activateConfigurationSet", &RTC::ConfigAdmin::activateConfigurationSet, py::arg("config_id"),
             WithoutGil())
        .def("addConfigurationSet", &RTC::ConfigAdmin::addConfigurationSet, py::arg("configuration_set"),
             WithoutGil())
        .def("setConfigurationSetValues", &RTC::ConfigAdmin::setConfigurationSetValues, py::arg("config_set"),
             WithoutGil())
        .def("removeConfigurationSet", &RTC::ConfigAdmin::removeConfigurationSet, py::arg("config_id"),
             WithoutGil())
        .def("update", [](RTC::ConfigAdmin &admin, py::object set, py::object param) {
            const std::optional<std::string> setId
                = set.is_none() ? std::nullopt : std::optional(set.cast<std::string>());
            const std::optional<std::string> name
                = param.is_none() ? std::nullopt : std::optional(param.cast<std::string>());
            py::gil_scoped_release released;
            if (!setId)
                admin.update();
            else if (!name)
                admin.update(setId->c_str());
            else
                admin.update(setId->c_str(), name->c_str());
        }, py::arg("config_set") = py::none(), py::arg("config_param") = py::none());
}

/// The kinds of configuration listener a component notes (PyComponent::rememberListener()).
enum ListenerKind { ParamListener, SetListener, SetNameListener };

/**
 * Binds @p addName / @p removeName of one kind of configuration listener: adding wraps the Python
 * listener in a @p Made the component owns and notes which Python object it calls; removing finds
 * and removes that one.
 */
template <typename Made, typename Type, typename Listener>
void bindListenerKind(ComponentClass &component, ListenerKind kind, const char *addName, const char *removeName,
                      void (RTC::RTObject_impl::*add)(Type, Listener *, bool),
                      void (RTC::RTObject_impl::*remove)(Type, Listener *))
{
    component
        .def(addName, [kind, add](PyComponent &self, Type type, py::object listener, bool) {
            auto *made = new Made(listener);
            self.rememberListener(kind, int(type), listener, made);
            py::gil_scoped_release released; // see WithoutGil
            (self.*add)(type, made, true);
        }, py::arg("type"), py::arg("listener"), py::arg("autoclean") = true)
        .def(removeName, [kind, remove](PyComponent &self, Type type, py::object listener) {
            if (void *made = self.takeListener(kind, int(type), listener)) {
                py::gil_scoped_release released;
                (self.*remove)(type, static_cast<Made *>(made));
            }
        }, py::arg("type"), py::arg("listener"));
}

/// Adds the configuration methods to the component bridge (bound in pycomponent.cpp).
void bindComponentConfiguration(py::module_ &module)
{
    ComponentClass component = py::reinterpret_borrow<ComponentClass>(module.attr("Component"));
    component.def_property_readonly("_configsets", &PyComponent::getConfigService,
                                    py::return_value_policy::reference_internal);
    bindListenerKind<PyConfigurationParamListener>(component, ParamListener, "addConfigurationParamListener",
                                                   "removeConfigurationParamListener",
                                                   &RTC::RTObject_impl::addConfigurationParamListener,
                                                   &RTC::RTObject_impl::removeConfigurationParamListener);
    bindListenerKind<PyConfigurationSetListener>(component, SetListener, "addConfigurationSetListener",
                                                 "removeConfigurationSetListener",
                                                 &RTC::RTObject_impl::addConfigurationSetListener,
                                                 &RTC::RTObject_impl::removeConfigurationSetListener);
    bindListenerKind<PyConfigurationSetNameListener>(component, SetNameListener, "addConfigurationSetNameListener",
                                                     "removeConfigurationSetNameListener",
                                                     &RTC::RTObject_impl::addConfigurationSetNameListener,
                                                     &RTC::RTObject_impl::removeConfigurationSetNameListener);
}

} // namespace

void bindConfiguration(py::module_ &module)
{
    bindListenerTypes(module);
    bindConfigAdmin(module);
    bindComponentConfiguration(module);
}

} // namespace RtPython
