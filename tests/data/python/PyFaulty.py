#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component whose onExecute raises: the runtime must move it to the Error state, log the
# traceback and keep the process (and onReset) working. And a component class whose constructor
# raises: creating it fails, the process goes on.

import functools
import sys

import OpenRTM_aist
import RTC
from testspec import component_spec


spec = functools.partial(component_spec, description="Raises in its callbacks")


class PyFaulty(OpenRTM_aist.DataFlowComponentBase):
    def onExecute(self, ec_id):
        raise RuntimeError("faulty on purpose")

    def onReset(self, ec_id):
        print("PyFaulty reset")
        return RTC.RTC_OK


class PyBroken(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        raise ValueError("broken on purpose")


def PyFaultyInit(manager):
    for cls in (PyFaulty, PyBroken):
        manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec(cls.__name__)), cls, OpenRTM_aist.Delete)
    print("PyBroken created:", manager.createComponent("PyBroken"))
    manager.createComponent("PyFaulty")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyFaultyInit)
    mgr.activateManager()
    mgr.runManager()
