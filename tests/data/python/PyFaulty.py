#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component whose onExecute raises: the runtime must move it to the Error state, print the
# traceback and keep the process (and onReset) working.

import sys

import OpenRTM_aist
import RTC

faulty_spec = ["implementation_id", "PyFaulty",
               "type_name", "PyFaulty",
               "description", "Raises in onExecute",
               "version", "1.0",
               "vendor", "RT Studio tests",
               "category", "test",
               "activity_type", "DataFlowComponent",
               "max_instance", "1",
               "language", "Python",
               "lang_type", "script",
               ""]


class PyFaulty(OpenRTM_aist.DataFlowComponentBase):
    def onExecute(self, ec_id):
        raise RuntimeError("faulty on purpose")

    def onReset(self, ec_id):
        print("PyFaulty reset")
        return RTC.RTC_OK


def PyFaultyInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=faulty_spec), PyFaulty, OpenRTM_aist.Delete)
    manager.createComponent("PyFaulty")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyFaultyInit)
    mgr.activateManager()
    mgr.runManager()
