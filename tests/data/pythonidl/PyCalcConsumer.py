#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component requiring PyCalc::Calculator on its service port "Calc": once connected and
# active it makes each kind of call once and prints what came back, then "consumer: done".

import sys

import OpenRTM_aist
import PyCalc
import RTC
from omniORB import CORBA

consumer_spec = ["implementation_id", "PyCalcConsumer",
                 "type_name", "PyCalcConsumer",
                 "description", "Requires PyCalc::Calculator",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class PyCalcConsumer(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Calc")
        self._calc = OpenRTM_aist.CorbaConsumer(interfaceType=PyCalc.Calculator)
        self._port.registerConsumer("calc", "Calculator", self._calc)
        self.addPort(self._port)
        self._done = False
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        calc = self._calc._ptr()
        if self._done or CORBA.is_nil(calc):
            return RTC.RTC_OK
        self._done = True
        terms = [PyCalc.Term(1.5, "a"), PyCalc.Term(2.5, "b"), PyCalc.Term(2.0, "c")]
        print("consumer: total", calc.total(terms, PyCalc.ADD), calc.total(terms, PyCalc.MULTIPLY))
        print("consumer: split", calc.split(3.25))
        print("consumer: accumulate", calc.accumulate([1, 2, 3], 4))
        print("consumer: flip", calc.flip(PyCalc.ADD))
        time = calc.later(RTC.Time(100, 7), 20)
        print("consumer: later", time.sec, time.nsec)
        calc._set_name("renamed")
        print("consumer: name", calc._get_name(), "calls", calc._get_calls())
        try:
            calc.total(terms * 2, PyCalc.ADD)
            print("consumer: no exception")
        except PyCalc.TooMany as error:
            print("consumer: TooMany", error.limit, error.reason)
        try:
            calc.later(RTC.Time(0, 0), -1)
        except CORBA.UNKNOWN:
            print("consumer: UNKNOWN")
        print("consumer: done")
        return RTC.RTC_OK


def PyCalcConsumerInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=consumer_spec), PyCalcConsumer, OpenRTM_aist.Delete)
    manager.createComponent("PyCalcConsumer")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyCalcConsumerInit)
    mgr.activateManager()
    mgr.runManager()
