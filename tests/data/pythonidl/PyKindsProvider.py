#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component providing PyKinds::Echo (Kinds.idl) on its service port "Echo": wide
# characters and strings, unions, object references and any as parameters and results.

import sys

import OpenRTM_aist
import PyKinds__POA
import RTC
from omniORB import CORBA, any

provider_spec = ["implementation_id", "PyKindsProvider",
                 "type_name", "PyKindsProvider",
                 "description", "Provides PyKinds::Echo",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class Echo(PyKinds__POA.Echo):
    """Answers each call; relay() calls the reference it is given back (calls())."""

    def __init__(self):
        self._calls = 0

    def letter(self, c):
        self._calls += 1
        return c.upper(), c * 3

    def reversed(self, w):
        self._calls += 1
        return w[::-1]

    def swap(self, p, q):
        self._calls += 1
        return q, p

    def relay(self, other):
        self._calls += 1
        print("provider: relay of a reference that answers calls()", other.calls() if other else None)
        return other, self._this()

    def wrap(self, value):
        """The value as it came, and a string naming its type and value."""
        self._calls += 1
        return value, any.to_any("%s %r" % (value.typecode()._name, any.from_any(value)))

    def calls(self):
        return self._calls


class PyKindsProvider(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Echo")
        self._echo = Echo()
        self._port.registerProvider("echo", "Echo", self._echo)
        self.addPort(self._port)
        return RTC.RTC_OK


def PyKindsProviderInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=provider_spec), PyKindsProvider,
                            OpenRTM_aist.Delete)
    manager.createComponent("PyKindsProvider")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyKindsProviderInit)
    mgr.activateManager()
    mgr.runManager()
