#!/usr/bin/env python3
# -*- coding: utf-8 -*-

# <rtc-template block="description">
"""
SampleComp.py: Sample component with "all" port kinds
"""
# </rtc-template>

import sys
sys.path.append(".")

import RTC
import OpenRTM_aist

# Servant classes of the provided interfaces
# <rtc-template block="service_impl">
from SampleService_idl_example import *
# </rtc-template>

# IDL stubs for the data types and the required interfaces
# <rtc-template block="consumer_import">
import RTC
import Sample
import Sample__POA
# </rtc-template>

# The component type as the manager registers it (the profile's properties).
# <rtc-template block="module_spec">
samplecomp_spec = [
    "implementation_id", "SampleComp",
    "type_name", "SampleComp",
    "description", "Sample component with \"all\" port kinds",
    "version", "1.2.0",
    "vendor", "Example",
    "category", "Test",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "Python",
    "lang_type", "SCRIPT",
    "conf.default.gain_value", "10",
    "conf.default.mode", "fast",
    "conf.default.rate", "0.5",
    "conf.__widget__.gain_value", "slider.1",
    "conf.__widget__.mode", "radio",
    "conf.__constraints__.gain_value", "0<=x<=100",
    "conf.__constraints__.mode", "(fast,slow)",
    "conf.__type__.gain_value", "int",
    "conf.__type__.mode", "string",
    "conf.__type__.rate", "double",
    ""]
# </rtc-template>


class SampleComp(OpenRTM_aist.DataFlowComponentBase):
    """
    Sample component with "all" port kinds
    """

    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)

        # <rtc-template block="init_conf_param">
        # Amplification
        self._gain = [0]
        # 
        self._mode = ['']
        # 
        self._rate = [0.0]
        # </rtc-template>

        # <rtc-template block="init_ports">
        self._d_in = OpenRTM_aist.instantiateDataType(RTC.TimedLong)
        self._inIn = OpenRTM_aist.InPort("in", self._d_in)
        self._d_result = OpenRTM_aist.instantiateDataType(RTC.TimedDouble)
        self._resultOut = OpenRTM_aist.OutPort("out", self._d_result)
        self._EchoPortPort = OpenRTM_aist.CorbaPort("EchoPort")
        self._ClockPortPort = OpenRTM_aist.CorbaPort("ClockPort")
        self._echo0 = Echo_i()
        self._clock = OpenRTM_aist.CorbaConsumer(interfaceType=Sample.Clock)
        # </rtc-template>

    def onInitialize(self):
        # Ties each configuration parameter to its member, with its default.
        # <rtc-template block="bind_config">
        self.bindParameter("gain_value", self._gain, "10")
        self.bindParameter("mode", self._mode, "fast")
        self.bindParameter("rate", self._rate, "0.5")
        # </rtc-template>

        # Adds the profile's ports to the component.
        # <rtc-template block="registration">
        self.addInPort("in", self._inIn)
        self.addOutPort("out", self._resultOut)
        self._EchoPortPort.registerProvider("echo", "Sample::Echo", self._echo0)
        self.addPort(self._EchoPortPort)
        self._ClockPortPort.registerConsumer("clock", "Sample::Clock", self._clock)
        self.addPort(self._ClockPortPort)
        # </rtc-template>

        return RTC.RTC_OK

    # def onFinalize(self):
    #     return RTC.RTC_OK

    # def onStartup(self, ec_id):
    #     return RTC.RTC_OK

    # def onShutdown(self, ec_id):
    #     return RTC.RTC_OK

    def onActivated(self, ec_id):
        return RTC.RTC_OK

    # def onDeactivated(self, ec_id):
    #     return RTC.RTC_OK

    # def onAborting(self, ec_id):
    #     return RTC.RTC_OK

    # def onError(self, ec_id):
    #     return RTC.RTC_OK

    # def onReset(self, ec_id):
    #     return RTC.RTC_OK

    def onExecute(self, ec_id):
        return RTC.RTC_OK

    # def onStateUpdate(self, ec_id):
    #     return RTC.RTC_OK

    # def onRateChanged(self, ec_id):
    #     return RTC.RTC_OK

def SampleCompInit(manager):
    profile = OpenRTM_aist.Properties(defaults_str=samplecomp_spec)
    manager.registerFactory(profile, SampleComp, OpenRTM_aist.Delete)


def MyModuleInit(manager):
    SampleCompInit(manager)
    # Pass an --instance_name= option on to createComponent()
    instance_name = [i for i in sys.argv if "--instance_name=" in i]
    args = instance_name[0].replace("--", "?") if instance_name else ""
    manager.createComponent("SampleComp" + args)


def main():
    argv = [i for i in sys.argv if "--instance_name=" not in i]
    manager = OpenRTM_aist.Manager.init(argv)
    manager.setModuleInitProc(MyModuleInit)
    manager.activateManager()
    manager.runManager()


if __name__ == "__main__":
    main()
