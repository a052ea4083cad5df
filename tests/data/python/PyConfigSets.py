#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component with two configuration sets and every kind of configuration listener, which
# activates itself through its own execution context as OpenRTM-aist-Python's examples do. It
# prints the active set and its variables whenever they change, and what the listeners are told;
# with the set "fast" active it removes its parameter listener.

import sys

import OpenRTM_aist
import RTC

sets_spec = ["implementation_id", "PyConfigSets", "type_name", "PyConfigSets", "description", "Configuration sets",
             "version", "1.0", "vendor", "RT Studio tests", "category", "test",
             "activity_type", "DataFlowComponent", "max_instance", "1", "language", "Python",
             "lang_type", "script",
             "conf.default.gain", "2",
             "conf.default.names", "a,b",
             "conf.fast.gain", "40",
             "conf.fast.names", "x",
             ""]


class ParamPrinter(OpenRTM_aist.ConfigurationParamListener):
    def __call__(self, config_set_name, config_param_name):
        print("param", config_set_name, config_param_name)


class SetPrinter(OpenRTM_aist.ConfigurationSetListener):
    def __call__(self, config_set):
        print("set changed gain=%s" % config_set.getProperty("gain"))


class ActivationPrinter(OpenRTM_aist.ConfigurationSetNameListener):
    def __call__(self, config_set_name):
        print("activated", config_set_name)


class PyConfigSets(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._gain = [0]
        self._names = [[""]]
        self._printed = None
        self._reported = False

    def onInitialize(self):
        self.bindParameter("gain", self._gain, "2")
        self.bindParameter("names", self._names, "a,b")
        self._param_printer = ParamPrinter()
        self.addConfigurationParamListener(OpenRTM_aist.ConfigurationParamListenerType.ON_UPDATE_CONFIG_PARAM,
                                           self._param_printer)
        self.addConfigurationSetListener(OpenRTM_aist.ConfigurationSetListenerType.ON_SET_CONFIG_SET, SetPrinter())
        self.addConfigurationSetNameListener(OpenRTM_aist.ConfigurationSetNameListenerType.ON_ACTIVATE_CONFIG_SET,
                                             ActivationPrinter())
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        current = "set %s gain=%r names=%r" % (self._configsets.getActiveId(), self._gain, self._names[0])
        if current != self._printed:
            print(current)
            self._printed = current
        # Once the "fast" set is active, its parameters change without being told.
        if self._param_printer and self._configsets.getActiveId() == "fast":
            self.removeConfigurationParamListener(OpenRTM_aist.ConfigurationParamListenerType.ON_UPDATE_CONFIG_PARAM,
                                                  self._param_printer)
            self._param_printer = None
            print("param listener removed")
        return RTC.RTC_OK


def PyConfigSetsInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=sets_spec), PyConfigSets, OpenRTM_aist.Delete)
    component = manager.createComponent("PyConfigSets")
    context = component.get_owned_contexts()[0]
    assert context.set_rate(20.0) == RTC.RTC_OK
    assert context.activate_component(component._objref) == RTC.RTC_OK
    print("state", context.get_component_state(component._objref), "rate", context.get_rate())


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyConfigSetsInit)
    mgr.activateManager()
    mgr.runManager()
