#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component providing PyCalc::Calculator (Calc.idl, compiled by rtctl idl) on its service
# port "Calc": results, out and inout parameters, sequences, attributes and a user exception.

import sys

import OpenRTM_aist
import PyCalc
import PyCalc__POA
import RTC

provider_spec = ["implementation_id", "PyCalcProvider",
                 "type_name", "PyCalcProvider",
                 "description", "Provides PyCalc::Calculator",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class CalculatorServant(PyCalc__POA.Calculator):
    def __init__(self):
        self._name = "calculator"
        self._calls = 0

    def total(self, terms, mode):
        self._calls += 1
        if len(terms) > PyCalc.MAX_TERMS:
            raise PyCalc.TooMany(PyCalc.MAX_TERMS, "%d terms" % len(terms))
        result = 0.0 if mode == PyCalc.ADD else 1.0
        for term in terms:
            result = result + term.value if mode == PyCalc.ADD else result * term.value
        print("provider: total of", [term.label for term in terms])
        return result

    def split(self, value):
        self._calls += 1
        whole = int(value)
        return whole, value - whole

    def accumulate(self, values, add):
        self._calls += 1
        return sum(values) + add, values + [add]

    def flip(self, mode):
        self._calls += 1
        return PyCalc.MULTIPLY if mode == PyCalc.ADD else PyCalc.ADD

    def later(self, time, seconds):
        if seconds < 0:
            raise ValueError("no time before")  # not declared: the caller gets CORBA.UNKNOWN
        self._calls += 1
        return RTC.Time(time.sec + seconds, time.nsec)

    def _get_name(self):
        return self._name

    def _set_name(self, name):
        self._name = name

    def _get_calls(self):
        return self._calls


class PyCalcProvider(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Calc")
        self._servant = CalculatorServant()
        self._port.registerProvider("calc", "Calculator", self._servant)
        self.addPort(self._port)
        return RTC.RTC_OK


def PyCalcProviderInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=provider_spec), PyCalcProvider, OpenRTM_aist.Delete)
    manager.createComponent("PyCalcProvider")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyCalcProviderInit)
    mgr.activateManager()
    mgr.runManager()
