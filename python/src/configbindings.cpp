// SPDX-License-Identifier: MIT
// Configuration from Python as OpenRTM-aist-Python names it: the component's configuration sets
// (`self._configsets`) and the configuration listeners with their types.
#include "bindings.h"
#include "pycomponent.h"
#include "pyconfigurationlisteners.h"

#include <rtm/ConfigAdmin.h>

#include <pybind11/stl.h>

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

void bindConfigAdmin(py::module_ &module)
{
    py::class_<RTC::ConfigAdmin, std::unique_ptr<RTC::ConfigAdmin, py::nodelete>>(module, "ConfigAdmin")
        .def("getActiveId", &RTC::ConfigAdmin::getActiveId)
        .def("haveConfig", &RTC::ConfigAdmin::haveConfig, py::arg("config_id"))
        .def("isActive", &RTC::ConfigAdmin::isActive)
        .def("isChanged", &RTC::ConfigAdmin::isChanged)
        .def("isExist", &RTC::ConfigAdmin::isExist, py::arg("param_name"))
        .def("changedParameters", &RTC::ConfigAdmin::changedParameters)
        .def("getConfigurationSets", &configurationSets)
        .def("getConfigurationSet", [](RTC::ConfigAdmin &admin, const char *id) {
            return coil::Properties(admin.getConfigurationSet(id));
        }, py::arg("config_id"))
        .def("getActiveConfigurationSet", [](RTC::ConfigAdmin &admin) {
            return coil::Properties(admin.getActiveConfigurationSet());
        })
        .def("activateConfigurationSet", &RTC::ConfigAdmin::activateConfigurationSet, py::arg("config_id"))
        .def("addConfigurationSet", &RTC::ConfigAdmin::addConfigurationSet, py::arg("configuration_set"))
        .def("setConfigurationSetValues", &RTC::ConfigAdmin::setConfigurationSetValues, py::arg("config_set"))
        .def("removeConfigurationSet", &RTC::ConfigAdmin::removeConfigurationSet, py::arg("config_id"))
        .def("update", [](RTC::ConfigAdmin &admin, py::object set, py::object param) {
            if (set.is_none())
                admin.update();
            else if (param.is_none())
                admin.update(set.cast<std::string>().c_str());
            else
                admin.update(set.cast<std::string>().c_str(), param.cast<std::string>().c_str());
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
            (self.*add)(type, made, true);
        }, py::arg("type"), py::arg("listener"), py::arg("autoclean") = true)
        .def(removeName, [kind, remove](PyComponent &self, Type type, py::object listener) {
            if (void *made = self.takeListener(kind, int(type), listener))
                (self.*remove)(type, static_cast<Made *>(made));
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
