#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A Python component providing PyCanvas::Painter (Canvas.idl, which includes Shapes.idl of its
# folder, whose types are under #pragma prefix "example.org") on its service port "Paint".

import math
import sys

import OpenRTM_aist
import PyCanvas__POA
import PyShapes
import RTC

provider_spec = ["implementation_id", "PyPainterProvider",
                 "type_name", "PyPainterProvider",
                 "description", "Provides PyCanvas::Painter",
                 "version", "1.0",
                 "vendor", "RT Studio tests",
                 "category", "test",
                 "activity_type", "DataFlowComponent",
                 "max_instance", "1",
                 "language", "Python",
                 "lang_type", "script",
                 ""]


class Painter(PyCanvas__POA.Painter):
    def area(self, shape):
        if shape.radius <= 0:
            raise PyShapes.Degenerate("radius %g" % shape.radius)
        return math.pi * shape.radius ** 2

    def total(self, scene):
        print("provider: total of", scene.title)
        return sum(self.area(circle) for circle in scene.circles)


class PyPainterProvider(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._port = OpenRTM_aist.CorbaPort("Paint")
        self._painter = Painter()
        self._port.registerProvider("painter", "Painter", self._painter)
        self.addPort(self._port)
        return RTC.RTC_OK


def PyPainterProviderInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=provider_spec), PyPainterProvider,
                            OpenRTM_aist.Delete)
    manager.createComponent("PyPainterProvider")


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PyPainterProviderInit)
    mgr.activateManager()
    mgr.runManager()
