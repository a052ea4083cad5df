#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component requiring PyCanvas::Painter on its service port "Paint": once connected and
# active it calls an operation of the interface and one of its base (PyShapes::Drawer, under a
# #pragma prefix) that raises, prints what came back and the type ids, then "consumer: done".

import sys

import OpenRTM_aist
import PyCanvas
import PyShapes
import RTC
from omniORB import CORBA

consumer_spec = ["implementation_id", "PyPainterConsumer",
                 "type_name", "PyPainterConsumer",
                 "description", "Requires PyCanvas::Painter",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class PyPainterConsumer(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Paint")
        self._painter = OpenRTM_aist.CorbaConsumer(interfaceType=PyCanvas.Painter)
        self._port.registerConsumer("painter", "Painter", self._painter)
        self.addPort(self._port)
        self._done = False
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        painter = self._painter._ptr()
        if self._done or CORBA.is_nil(painter):
            return RTC.RTC_OK
        self._done = True
        print("consumer: ids", PyShapes.Circle._NP_RepositoryId, PyCanvas.Scene._NP_RepositoryId)
        scene = PyCanvas.Scene([PyShapes.Circle(1.0), PyShapes.Circle(2.0)], "two circles")
        print("consumer: total %.4f" % painter.total(scene))
        try:
            painter.area(PyShapes.Circle(0.0))
            print("consumer: no exception")
        except PyShapes.Degenerate as error:
            print("consumer: Degenerate", error.why)
        print("consumer: done")
        return RTC.RTC_OK


def PyPainterConsumerInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=consumer_spec), PyPainterConsumer,
                            OpenRTM_aist.Delete)
    manager.createComponent("PyPainterConsumer")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyPainterConsumerInit)
    mgr.activateManager()
    mgr.runManager()
