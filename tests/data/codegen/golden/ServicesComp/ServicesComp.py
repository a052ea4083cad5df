#!/usr/bin/env python3
# -*- coding: utf-8 -*-

# <rtc-template block="description">
"""
ServicesComp.py: Provided and required services from a multi-module IDL
"""
# </rtc-template>

import sys
sys.path.append(".")

import RTC
import OpenRTM_aist

# Servant classes of the provided interfaces
# <rtc-template block="service_impl">
from Robotics_idl_example import *
# </rtc-template>

# IDL stubs for the data types and the required interfaces
# <rtc-template block="consumer_import">
import Nav
import Nav__POA
import Robot
import Robot__POA.Control
# </rtc-template>

# The component type as the manager registers it (the profile's properties).
# <rtc-template block="module_spec">
servicescomp_spec = [
    "implementation_id", "ServicesComp",
    "type_name", "ServicesComp",
    "description", "Provided and required services from a multi-module IDL",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Controller",
    "activity_type", "SPORADIC",
    "kind", "DataFlowComponent",
    "max_instance", "0",
    "language", "Python",
    "lang_type", "SCRIPT",
    ""]
# </rtc-template>


class ServicesComp(OpenRTM_aist.DataFlowComponentBase):
    """
    Provided and required services from a multi-module IDL
    """

    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)

        # <rtc-template block="init_conf_param">
        # </rtc-template>

        # <rtc-template block="init_ports">
        self._MotorPortPort = OpenRTM_aist.CorbaPort("MotorPort")
        self._PlannerPortPort = OpenRTM_aist.CorbaPort("PlannerPort")
        self._DevicePortPort = OpenRTM_aist.CorbaPort("DevicePort")
        self._motor = Motor_i()
        self._plannerImpl = Planner_i()
        self._mapperRef = OpenRTM_aist.CorbaConsumer(interfaceType=Robot.Geometry.Mapper)
        self._device = OpenRTM_aist.CorbaConsumer(interfaceType=Robot.Control.Device)
        self._driver = OpenRTM_aist.CorbaConsumer(interfaceType=Robot.Control.Motor)
        # </rtc-template>

    def onInitialize(self):
        # Ties each configuration parameter to its member, with its default.
        # <rtc-template block="bind_config">
        # </rtc-template>

        # Adds the profile's ports to the component.
        # <rtc-template block="registration">
        self._MotorPortPort.registerProvider("motor0", "Robot::Control::Motor", self._motor)
        self.addPort(self._MotorPortPort)
        self._PlannerPortPort.registerProvider("planner", "Nav::Planner", self._plannerImpl)
        self._PlannerPortPort.registerConsumer("mapper", "Robot::Geometry::Mapper", self._mapperRef)
        self.addPort(self._PlannerPortPort)
        self._DevicePortPort.registerConsumer("device", "Robot::Control::Device", self._device)
        self._DevicePortPort.registerConsumer("driver", "Robot::Control::Motor", self._driver)
        self.addPort(self._DevicePortPort)
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

def ServicesCompInit(manager):
    profile = OpenRTM_aist.Properties(defaults_str=servicescomp_spec)
    manager.registerFactory(profile, ServicesComp, OpenRTM_aist.Delete)


def MyModuleInit(manager):
    ServicesCompInit(manager)
    # Pass an --instance_name= option on to createComponent()
    instance_name = [i for i in sys.argv if "--instance_name=" in i]
    args = instance_name[0].replace("--", "?") if instance_name else ""
    manager.createComponent("ServicesComp" + args)


def main():
    argv = [i for i in sys.argv if "--instance_name=" not in i]
    manager = OpenRTM_aist.Manager.init(argv)
    manager.setModuleInitProc(MyModuleInit)
    manager.activateManager()
    manager.runManager()


if __name__ == "__main__":
    main()
