#!/usr/bin/env python3
# -*- coding: utf-8 -*-

# <rtc-template block="description">
"""
DocumentedComp.py: A component with every documentation field
"""
# </rtc-template>

import sys
sys.path.append(".")

import RTC
import OpenRTM_aist

# Servant classes of the provided interfaces
# <rtc-template block="service_impl">
# </rtc-template>

# IDL stubs for the data types and the required interfaces
# <rtc-template block="consumer_import">
import RTC
import Sample
# </rtc-template>

# The component type as the manager registers it (the profile's properties).
# <rtc-template block="module_spec">
documentedcomp_spec = [
    "implementation_id", "DocumentedComp",
    "type_name", "DocumentedComp",
    "description", "A component with every documentation field",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Sensor",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "Python",
    "lang_type", "SCRIPT",
    "conf.default.period", "0.1",
    "conf.__widget__.period", "text",
    "conf.__constraints__.period", "0.01<=x<=1.0",
    "conf.__type__.period", "double",
    ""]
# </rtc-template>


class DocumentedComp(OpenRTM_aist.DataFlowComponentBase):
    """
    A component with every documentation field
    """

    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)

        # <rtc-template block="init_conf_param">
        # Sampling period of the sensor
        self._period = [0.0]
        # </rtc-template>

        # <rtc-template block="init_ports">
        self._d_command = OpenRTM_aist.instantiateDataType(RTC.TimedLong)
        self._commandIn = OpenRTM_aist.InPort("command", self._d_command)
        self._d_status = OpenRTM_aist.instantiateDataType(RTC.TimedString)
        self._statusOut = OpenRTM_aist.OutPort("status", self._d_status)
        self._ClockPortPort = OpenRTM_aist.CorbaPort("ClockPort")
        self._clock = OpenRTM_aist.CorbaConsumer(interfaceType=Sample.Clock)
        # </rtc-template>

    def onInitialize(self):
        # Ties each configuration parameter to its member, with its default.
        # <rtc-template block="bind_config">
        self.bindParameter("period", self._period, "0.1")
        # </rtc-template>

        # Adds the profile's ports to the component.
        # <rtc-template block="registration">
        self.addInPort("command", self._commandIn)
        self.addOutPort("status", self._statusOut)
        self._ClockPortPort.registerConsumer("clock", "Sample::Clock", self._clock)
        self.addPort(self._ClockPortPort)
        # </rtc-template>

        return RTC.RTC_OK

    def onFinalize(self):
        return RTC.RTC_OK

    def onStartup(self, ec_id):
        return RTC.RTC_OK

    def onShutdown(self, ec_id):
        return RTC.RTC_OK

    def onActivated(self, ec_id):
        return RTC.RTC_OK

    def onDeactivated(self, ec_id):
        return RTC.RTC_OK

    def onAborting(self, ec_id):
        return RTC.RTC_OK

    def onError(self, ec_id):
        return RTC.RTC_OK

    def onReset(self, ec_id):
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        return RTC.RTC_OK

    def onStateUpdate(self, ec_id):
        return RTC.RTC_OK

    def onRateChanged(self, ec_id):
        return RTC.RTC_OK

def DocumentedCompInit(manager):
    profile = OpenRTM_aist.Properties(defaults_str=documentedcomp_spec)
    manager.registerFactory(profile, DocumentedComp, OpenRTM_aist.Delete)


def MyModuleInit(manager):
    DocumentedCompInit(manager)
    # Pass an --instance_name= option on to createComponent()
    instance_name = [i for i in sys.argv if "--instance_name=" in i]
    args = instance_name[0].replace("--", "?") if instance_name else ""
    manager.createComponent("DocumentedComp" + args)


def main():
    argv = [i for i in sys.argv if "--instance_name=" not in i]
    manager = OpenRTM_aist.Manager.init(argv)
    manager.setModuleInitProc(MyModuleInit)
    manager.activateManager()
    manager.runManager()


if __name__ == "__main__":
    main()
