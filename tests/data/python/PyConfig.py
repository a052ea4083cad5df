#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component with configuration parameters bound as OpenRTM-aist-Python binds them (lists
# of one value): it prints them whenever they change.

import sys

import OpenRTM_aist
import RTC

config_spec = ["implementation_id", "PyConfig", "type_name", "PyConfig", "description", "Configuration",
               "version", "1.0", "vendor", "RT Studio tests", "category", "test",
               "activity_type", "DataFlowComponent", "max_instance", "1", "language", "Python",
               "lang_type", "script",
               "conf.default.int_param", "1",
               "conf.default.double_param", "0.5",
               "conf.default.str_param", "text",
               "conf.default.vector_param", "1.5,2.5",
               "conf.default.flag_param", "false",
               ""]


class PyConfig(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._int_param = [0]
        self._double_param = [0.0]
        self._str_param = [""]
        self._vector_param = [[0.0]]
        self._flag_param = [True]
        self._printed = None

    def onInitialize(self):
        self.bindParameter("int_param", self._int_param, "1")
        self.bindParameter("double_param", self._double_param, "0.5")
        self.bindParameter("str_param", self._str_param, "text")
        self.bindParameter("vector_param", self._vector_param, "1.5,2.5")
        self.bindParameter("flag_param", self._flag_param, "false")
        assert not self.bindParameter("int_param", self._int_param, "2"), "a name bound twice"
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        current = "int_param=%r double_param=%r str_param=%r vector_param=%r flag_param=%r" % (
            self._int_param[0], self._double_param[0], self._str_param[0], self._vector_param[0],
            self._flag_param[0])
        if current != self._printed:
            print(current)
            self._printed = current
        return RTC.RTC_OK


def PyConfigInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=config_spec), PyConfig, OpenRTM_aist.Delete)
    manager.createComponent("PyConfig")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyConfigInit)
    mgr.activateManager()
    mgr.runManager()
