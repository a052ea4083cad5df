#!/usr/bin/env python3
# -*- coding: utf-8 -*-

# <rtc-template block="description">
"""
DataPortsComp.py: Data ports of many types
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
dataportscomp_spec = [
    "implementation_id", "DataPortsComp",
    "type_name", "DataPortsComp",
    "description", "Data ports of many types",
    "version", "1.0.0",
    "vendor", "Example",
    "category", "Converter",
    "activity_type", "PERIODIC",
    "kind", "DataFlowComponent",
    "max_instance", "1",
    "language", "Python",
    "lang_type", "SCRIPT",
    ""]
# </rtc-template>


class DataPortsComp(OpenRTM_aist.DataFlowComponentBase):
    """
    Data ports of many types
    """

    def __init__(self, manager):
        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)

        # <rtc-template block="init_conf_param">
        # </rtc-template>

        # <rtc-template block="init_ports">
        self._d_in_long = OpenRTM_aist.instantiateDataType(RTC.TimedLong)
        self._in_longIn = OpenRTM_aist.InPort("in_long", self._d_in_long)
        self._d_doubles = OpenRTM_aist.instantiateDataType(RTC.TimedDoubleSeq)
        self._doublesIn = OpenRTM_aist.InPort("in_doubles", self._d_doubles)
        self._d_in_text = OpenRTM_aist.instantiateDataType(RTC.TimedString)
        self._in_textIn = OpenRTM_aist.InPort("in_text", self._d_in_text)
        self._d_in_pose = OpenRTM_aist.instantiateDataType(RTC.TimedPose2D)
        self._in_poseIn = OpenRTM_aist.InPort("in_pose", self._d_in_pose)
        self._d_image = OpenRTM_aist.instantiateDataType(RTC.CameraImage)
        self._imageIn = OpenRTM_aist.InPort("in_image", self._d_image)
        self._d_out_wide = OpenRTM_aist.instantiateDataType(RTC.TimedWString)
        self._out_wideOut = OpenRTM_aist.OutPort("out_wide", self._d_out_wide)
        self._d_out_octets = OpenRTM_aist.instantiateDataType(RTC.TimedOctetSeq)
        self._out_octetsOut = OpenRTM_aist.OutPort("out_octets", self._d_out_octets)
        self._d_out_flags = OpenRTM_aist.instantiateDataType(RTC.TimedBooleanSeq)
        self._out_flagsOut = OpenRTM_aist.OutPort("out_flags", self._d_out_flags)
        self._d_out_vector = OpenRTM_aist.instantiateDataType(RTC.TimedVector3D)
        self._out_vectorOut = OpenRTM_aist.OutPort("out_vector", self._d_out_vector)
        self._d_ranges = OpenRTM_aist.instantiateDataType(RTC.RangeData)
        self._rangesOut = OpenRTM_aist.OutPort("out_range", self._d_ranges)
        self._d_out_cloud = OpenRTM_aist.instantiateDataType(RTC.PointCloud)
        self._out_cloudOut = OpenRTM_aist.OutPort("out_cloud", self._d_out_cloud)
        # </rtc-template>

    def onInitialize(self):
        # Ties each configuration parameter to its member, with its default.
        # <rtc-template block="bind_config">
        # </rtc-template>

        # Adds the profile's ports to the component.
        # <rtc-template block="registration">
        self.addInPort("in_long", self._in_longIn)
        self.addInPort("in_doubles", self._doublesIn)
        self.addInPort("in_text", self._in_textIn)
        self.addInPort("in_pose", self._in_poseIn)
        self.addInPort("in_image", self._imageIn)
        self.addOutPort("out_wide", self._out_wideOut)
        self.addOutPort("out_octets", self._out_octetsOut)
        self.addOutPort("out_flags", self._out_flagsOut)
        self.addOutPort("out_vector", self._out_vectorOut)
        self.addOutPort("out_range", self._rangesOut)
        self.addOutPort("out_cloud", self._out_cloudOut)
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

    def onDeactivated(self, ec_id):
        return RTC.RTC_OK

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

def DataPortsCompInit(manager):
    profile = OpenRTM_aist.Properties(defaults_str=dataportscomp_spec)
    manager.registerFactory(profile, DataPortsComp, OpenRTM_aist.Delete)


def MyModuleInit(manager):
    DataPortsCompInit(manager)
    # Pass an --instance_name= option on to createComponent()
    instance_name = [i for i in sys.argv if "--instance_name=" in i]
    args = instance_name[0].replace("--", "?") if instance_name else ""
    manager.createComponent("DataPortsComp" + args)


def main():
    argv = [i for i in sys.argv if "--instance_name=" not in i]
    manager = OpenRTM_aist.Manager.init(argv)
    manager.setModuleInitProc(MyModuleInit)
    manager.activateManager()
    manager.runManager()


if __name__ == "__main__":
    main()
