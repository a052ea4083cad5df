#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component with both sides of SimpleService::MyService, interface instance "myservice"
# as rtmanager's C++ built-ins name it: port "Provided" offers a Python servant, port "Required"
# calls the provider it is connected to once it is active, and prints the answers.

import sys

import OpenRTM_aist
import RTC
import SimpleService
import SimpleService__POA
from omniORB import CORBA

spec = ["implementation_id", "PyMyService",
        "type_name", "PyMyService",
        "description", "Provides and requires SimpleService::MyService",
        "version", "1.0",
        "vendor", "RT Studio tests",
        "category", "test",
        "activity_type", "DataFlowComponent",
        "max_instance", "1",
        "language", "Python",
        "lang_type", "script",
        ""]


class MyServiceServant(SimpleService__POA.MyService):
    def __init__(self):
        self._echoes = []
        self._values = []

    def echo(self, msg):
        self._echoes.append(msg)
        print("servant: echo", msg)
        return "python says " + msg

    def get_echo_history(self):
        return self._echoes

    def set_value(self, value):
        self._values.append(value)

    def get_value(self):
        return self._values[-1] if self._values else 0.0

    def get_value_history(self):
        return self._values


class PyMyService(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._provided = OpenRTM_aist.CorbaPort("Provided")
        self._servant = MyServiceServant()
        self._provided.registerProvider("myservice", "SimpleService::MyService", self._servant)
        self.addPort(self._provided)
        self._required = OpenRTM_aist.CorbaPort("Required")
        self._service = OpenRTM_aist.CorbaConsumer(interfaceType=SimpleService.MyService)
        self._required.registerConsumer("myservice", "SimpleService::MyService", self._service)
        self.addPort(self._required)
        self._called = False
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        service = self._service._ptr()
        if self._called or CORBA.is_nil(service):
            return RTC.RTC_OK
        self._called = True
        print("consumer: echo", service.echo("from python"))
        service.set_value(1.25)
        service.set_value(2.5)
        print("consumer: value", service.get_value(), "history", service.get_value_history())
        print("consumer: echoes", service.get_echo_history())
        return RTC.RTC_OK


def PyMyServiceInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec), PyMyService, OpenRTM_aist.Delete)
    manager.createComponent("PyMyService")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyMyServiceInit)
    mgr.activateManager()
    mgr.runManager()
