#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component requiring PyKinds::Echo on its service port "Echo": once connected and active
# it makes each call once with wide characters, unions and object references (its own servant's,
# activated with _this(), and the ORB's string_to_object of its IOR) and prints what came back.

import sys

import OpenRTM_aist
import PyKinds
import PyKinds__POA
import RTC
from omniORB import CORBA, any

consumer_spec = ["implementation_id", "PyKindsConsumer",
                 "type_name", "PyKindsConsumer",
                 "description", "Requires PyKinds::Echo",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class LocalEcho(PyKinds__POA.Echo):
    """A servant of this process, passed to the provider as a reference to call back."""

    def calls(self):
        return 42


class PyKindsConsumer(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Echo")
        self._echo = OpenRTM_aist.CorbaConsumer(interfaceType=PyKinds.Echo)
        self._port.registerConsumer("echo", "Echo", self._echo)
        self.addPort(self._port)
        self._done = False
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        echo = self._echo._ptr()
        if self._done or CORBA.is_nil(echo):
            return RTC.RTC_OK
        self._done = True
        print("consumer: letter", echo.letter("\u00e9"))
        print("consumer: reversed", echo.reversed("h\u00e9llo \u4e16"))
        print("consumer: swap", echo.swap(PyKinds.Pick(number=5), PyKinds.Pick(text="t")))
        for value in (any.to_any(2.5), any.to_any("corba_cdr"), CORBA.Any(CORBA.TC_ushort, 7),
                      any.to_any(PyKinds.Pick(number=5)), any.to_any(RTC.Time(1, 2)),
                      CORBA.Any(CORBA.TC_TypeCode, PyKinds._tc_Pick), any.to_any([1, 2])):
            same, described = echo.wrap(value)
            print("consumer: wrap", same == value, any.from_any(described))
        orb = CORBA.ORB_init(sys.argv)
        local = LocalEcho()._this()
        again = orb.string_to_object(orb.object_to_string(local))
        print("consumer: string_to_object", type(again).__name__, again.calls())
        relayed, provider = echo.relay(local)
        print("consumer: relay", relayed.calls(), type(provider).__name__, provider.calls() >= 4)
        print("consumer: relay nil", echo.relay(None)[0])
        print("consumer: done")
        return RTC.RTC_OK


def PyKindsConsumerInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=consumer_spec), PyKindsConsumer,
                            OpenRTM_aist.Delete)
    manager.createComponent("PyKindsConsumer")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyKindsConsumerInit)
    mgr.activateManager()
    mgr.runManager()
