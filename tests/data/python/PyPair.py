#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Two Python components in one process, a source counting on its OutPort and a sink printing what
# its InPort receives, for connections whose both ends live in the same process.

import functools
import sys

import OpenRTM_aist
import RTC
from testspec import component_spec


spec = functools.partial(component_spec, description="Same-process pair")


class PySource(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._data = RTC.TimedLong(RTC.Time(0, 0), 0)
        self._outport = OpenRTM_aist.OutPort("out", self._data)
        self.addOutPort("out", self._outport)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        self._data.data += 1
        self._outport.write()
        return RTC.RTC_OK


class PySink(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._inport = OpenRTM_aist.InPort("in", RTC.TimedLong(RTC.Time(0, 0), 0))
        self.addInPort("in", self._inport)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        while self._inport.isNew():
            print("sink got", self._inport.read().data)
        return RTC.RTC_OK


def PyPairInit(manager):
    for cls in (PySource, PySink):
        manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec(cls.__name__)), cls, OpenRTM_aist.Delete)
        manager.createComponent(cls.__name__)


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyPairInit)
    mgr.activateManager()
    mgr.runManager()
