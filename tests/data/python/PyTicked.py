#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component meant for an ExtTrigExecutionContext (exec_cxt.periodic.type in its rtc.conf):
# it activates itself and ticks its own context three times through the context's object reference,
# printing each cycle it runs.

import sys

import OpenRTM_aist
import RTC

ticked_spec = ["implementation_id", "PyTicked", "type_name", "PyTicked", "description", "Steps when ticked",
               "version", "1.0", "vendor", "RT Studio tests", "category", "test",
               "activity_type", "DataFlowComponent", "max_instance", "1", "language", "Python",
               "lang_type", "script", ""]


class PyTicked(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._cycles = 0

    def onExecute(self, ec_id):
        self._cycles += 1
        print("cycle", self._cycles)
        return RTC.RTC_OK


def PyTickedInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=ticked_spec), PyTicked, OpenRTM_aist.Delete)
    component = manager.createComponent("PyTicked")
    context = component.getExecutionContext(0)
    assert context.activate_component(component.getObjRef()) == RTC.RTC_OK
    for _ in range(3):
        context.tick()


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyTickedInit)
    mgr.activateManager()
    mgr.runManager()
