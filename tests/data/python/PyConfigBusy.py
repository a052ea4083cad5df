#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component that asks its configuration for the active set over and over while it
# executes, with a set listener and a parameter listener: configuration changes made from outside
# (rtctl conf set) reach the listeners while its execution context holds the interpreter. It
# prints its gain whenever the gain changes and counts what the listeners are told.

import sys

import OpenRTM_aist
import RTC

busy_spec = ["implementation_id", "PyConfigBusy", "type_name", "PyConfigBusy", "description", "Busy configuration",
             "version", "1.0", "vendor", "RT Studio tests", "category", "test",
             "activity_type", "DataFlowComponent", "max_instance", "1", "language", "Python",
             "lang_type", "script",
             "conf.default.gain", "0",
             ""]


class Counter:
    def __init__(self):
        self.count = 0


class SetCounter(OpenRTM_aist.ConfigurationSetListener):
    def __init__(self, counter):
        self._counter = counter

    def __call__(self, config_set):
        self._counter.count += 1


class ParamCounter(OpenRTM_aist.ConfigurationParamListener):
    def __init__(self, counter):
        self._counter = counter

    def __call__(self, config_set_name, config_param_name):
        self._counter.count += 1


class PyConfigBusy(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._gain = [0]
        self._printed = None
        self._sets = Counter()
        self._params = Counter()

    def onInitialize(self):
        self.bindParameter("gain", self._gain, "0")
        self.addConfigurationSetListener(OpenRTM_aist.ConfigurationSetListenerType.ON_SET_CONFIG_SET,
                                         SetCounter(self._sets))
        self.addConfigurationParamListener(OpenRTM_aist.ConfigurationParamListenerType.ON_UPDATE_CONFIG_PARAM,
                                           ParamCounter(self._params))
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        for _ in range(2000):
            self._configsets.getActiveId()
            self._configsets.isChanged()
        current = "gain %r sets told %d params told %d" % (self._gain, self._sets.count, self._params.count)
        if current != self._printed:
            print(current, flush=True)
            self._printed = current
        return RTC.RTC_OK


def PyConfigBusyInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=busy_spec), PyConfigBusy, OpenRTM_aist.Delete)
    component = manager.createComponent("PyConfigBusy")
    context = component.get_owned_contexts()[0]
    assert context.activate_component(component._objref) == RTC.RTC_OK
    print("busy", context.get_component_state(component._objref), flush=True)


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyConfigBusyInit)
    mgr.activateManager()
    mgr.runManager()
