#!/usr/bin/env python3
# -*- coding: utf-8 -*-

# <rtc-template block="description">
"""
ConfigComp.py: Configuration with every widget and constraint
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
# </rtc-template>

# The component type as the manager registers it (the profile's properties).
# <rtc-template block="module_spec">
configcomp_spec = [
    "implementation_id", "ConfigComp",
    "type_name", "ConfigComp",
    "description", "Configuration with every widget and constraint",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Controller",
    "activity_type", "EVENTDRIVEN",
    "kind", "DataFlowComponent",
    "max_instance", "4",
    "language", "Python",
    "lang_type", "SCRIPT",
    "conf.default.label", "hello world",
    "conf.default.gain", "1.5",
    "conf.default.count", "3",
    "conf.default.threshold", "10",
    "conf.default.limit", "5",
    "conf.default.mode", "fast",
    "conf.default.features", "camera,lidar",
    "conf.default.order", "first,second",
    "conf.default.weights", "0.5,1.5",
    "conf.default.scale", "0.25",
    "conf.default.target", "42",
    "conf.__widget__.label", "text",
    "conf.__widget__.gain", "slider.0.5",
    "conf.__widget__.count", "spin",
    "conf.__widget__.threshold", "text",
    "conf.__widget__.mode", "radio",
    "conf.__widget__.features", "checkbox",
    "conf.__widget__.order", "ordered_list",
    "conf.__widget__.weights", "text",
    "conf.__widget__.scale", "spin",
    "conf.__constraints__.gain", "0<=x<=10",
    "conf.__constraints__.count", "0<=x<=100",
    "conf.__constraints__.threshold", "x>0",
    "conf.__constraints__.limit", "x<8",
    "conf.__constraints__.mode", "(fast,slow,idle)",
    "conf.__constraints__.features", "(camera,lidar,sonar)",
    "conf.__constraints__.order", "(first,second,third)",
    "conf.__constraints__.weights", "0<=x<=1,0<=x<=2",
    "conf.__constraints__.scale", "x>=0",
    "conf.__constraints__.target", "42",
    "conf.__type__.label", "string",
    "conf.__type__.gain", "double",
    "conf.__type__.count", "int",
    "conf.__type__.threshold", "long",
    "conf.__type__.limit", "short",
    "conf.__type__.mode", "string",
    "conf.__type__.features", "string",
    "conf.__type__.order", "vector<string>",
    "conf.__type__.weights", "vector<double>",
    "conf.__type__.scale", "float",
    "conf.__type__.target", "long",
    ""]
# </rtc-template>


class ConfigComp(OpenRTM_aist.DataFlowComponentBase):
    """
    Configuration with every widget and constraint
    """

    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)

        # <rtc-template block="init_conf_param">
        # 
        self._label = ['']
        # 
        self._gainValue = [0.0]
        # 
        self._count = [0]
        # 
        self._threshold = [0]
        # 
        self._limit = [0]
        # 
        self._mode = ['']
        # 
        self._features = ['']
        # 
        self._order = [['']]
        # 
        self._weights = [[0.0]]
        # 
        self._scale = [0.0]
        # 
        self._target = [0]
        # </rtc-template>

        # <rtc-template block="init_ports">
        self._d_in = OpenRTM_aist.instantiateDataType(RTC.TimedDouble)
        self._inIn = OpenRTM_aist.InPort("in", self._d_in)
        self._d_out = OpenRTM_aist.instantiateDataType(RTC.TimedDouble)
        self._outOut = OpenRTM_aist.OutPort("out", self._d_out)
        # </rtc-template>

    def onInitialize(self):
        # Ties each configuration parameter to its member, with its default.
        # <rtc-template block="bind_config">
        self.bindParameter("label", self._label, "hello world")
        self.bindParameter("gain", self._gainValue, "1.5")
        self.bindParameter("count", self._count, "3")
        self.bindParameter("threshold", self._threshold, "10")
        self.bindParameter("limit", self._limit, "5")
        self.bindParameter("mode", self._mode, "fast")
        self.bindParameter("features", self._features, "camera,lidar")
        self.bindParameter("order", self._order, "first,second")
        self.bindParameter("weights", self._weights, "0.5,1.5")
        self.bindParameter("scale", self._scale, "0.25")
        self.bindParameter("target", self._target, "42")
        # </rtc-template>

        # Adds the profile's ports to the component.
        # <rtc-template block="registration">
        self.addInPort("in", self._inIn)
        self.addOutPort("out", self._outOut)
        # </rtc-template>

        return RTC.RTC_OK

    # def onFinalize(self):
    #     return RTC.RTC_OK

    # def onStartup(self, ec_id):
    #     return RTC.RTC_OK

    # def onShutdown(self, ec_id):
    #     return RTC.RTC_OK

    # def onActivated(self, ec_id):
    #     return RTC.RTC_OK

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

def ConfigCompInit(manager):
    profile = OpenRTM_aist.Properties(defaults_str=configcomp_spec)
    manager.registerFactory(profile, ConfigComp, OpenRTM_aist.Delete)


def MyModuleInit(manager):
    ConfigCompInit(manager)
    # Pass an --instance_name= option on to createComponent()
    instance_name = [i for i in sys.argv if "--instance_name=" in i]
    args = instance_name[0].replace("--", "?") if instance_name else ""
    manager.createComponent("ConfigComp" + args)


def main():
    argv = [i for i in sys.argv if "--instance_name=" not in i]
    manager = OpenRTM_aist.Manager.init(argv)
    manager.setModuleInitProc(MyModuleInit)
    manager.activateManager()
    manager.runManager()


if __name__ == "__main__":
    main()
