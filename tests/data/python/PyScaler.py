#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component with an InPort and an OutPort (TimedLong): every sample it reads is sent on
# multiplied by 1000, so a sink downstream can tell what went through it.

import sys

import OpenRTM_aist
import RTC

scaler_spec = ["implementation_id", "PyScaler",
               "type_name", "PyScaler",
               "description", "Multiplies TimedLong samples by 1000",
               "version", "1.0",
               "vendor", "RT Studio tests",
               "category", "test",
               "activity_type", "DataFlowComponent",
               "max_instance", "1",
               "language", "Python",
               "lang_type", "script",
               ""]


class PyScaler(OpenRTM_aist.DataFlowComponentBase):
    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)
        self._d_in = RTC.TimedLong(RTC.Time(0, 0), 0)
        self._d_out = RTC.TimedLong(RTC.Time(0, 0), 0)

    def onInitialize(self):
        self._inport = OpenRTM_aist.InPort("in", self._d_in)
        self._outport = OpenRTM_aist.OutPort("out", self._d_out)
        self.addInPort("in", self._inport)
        self.addOutPort("out", self._outport)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        while self._inport.isNew():
            sample = self._inport.read()
            self._d_out.data = sample.data * 1000
            OpenRTM_aist.setTimestamp(self._d_out)
            self._outport.write()
            print(f"scaled {sample.data}")
        return RTC.RTC_OK


def PyScalerInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=scaler_spec), PyScaler, OpenRTM_aist.Delete)
    manager.createComponent("PyScaler")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyScalerInit)
    mgr.activateManager()
    mgr.runManager()
