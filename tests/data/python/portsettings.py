#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# rtc.conf's port settings as OpenRTM-aist's ports take them: port.inport.<name>.* (and
# port.inport.dataport.* for every InPort) are the defaults of each connection's settings, and a
# connector's own settings come first. Three InPorts whose connections keep 2, 3 and 4 samples (the
# buffers overwrite the oldest) each receive five samples. Exits non-zero on the first failure;
# prints "portsettings: ok" at the end.

import functools
import sys

import OpenRTM_aist
import RTC
from testspec import component_spec

made = {}
spec = functools.partial(component_spec, description="Port settings test")


class Writer(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.out = OpenRTM_aist.OutPort("out", RTC.TimedLong(RTC.Time(0, 0), 0))
        self.addOutPort("out", self.out)
        made["writer"] = self
        return RTC.RTC_OK


class Reader(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.ports = {name: OpenRTM_aist.InPort(name, RTC.TimedLong(RTC.Time(0, 0), 0))
                      for name in ("named", "other", "overridden")}
        for name, port in self.ports.items():
            self.addInPort(name, port)
        made["reader"] = self
        return RTC.RTC_OK


def init(manager):
    for cls in (Writer, Reader):
        manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec(cls.__name__)), cls, OpenRTM_aist.Delete)
        manager.createComponent(cls.__name__)


preconnect = ", ".join(["Writer0.out?port=Reader0.named", "Writer0.out?port=Reader0.other",
                        "Writer0.out?port=Reader0.overridden&buffer.length=4"])
mgr = OpenRTM_aist.Manager.init([sys.argv[0], "-o", "naming.enable: NO", "-o", "corba.master_manager:",
                                 "-o", "logger.enable: NO",
                                 "-o", "manager.components.preconnect: " + preconnect,
                                 "-o", "port.inport.dataport.buffer.length: 3",
                                 "-o", "port.inport.named.buffer.length: 2",
                                 "-o", "port.inport.overridden.buffer.length: 2"])
mgr.setModuleInitProc(init)
mgr.activateManager()
mgr.runManager(True)

writer, reader = made["writer"], made["reader"]
for value in range(1, 6):
    writer.out.write(RTC.TimedLong(RTC.Time(0, 0), value))
expected = {"named": [4, 5], "other": [3, 4, 5], "overridden": [2, 3, 4, 5]}
for name, port in reader.ports.items():
    got = []
    while port.isNew():
        got.append(port.read().data)
    if got != expected[name]:
        print("portsettings: FAILED: %s kept %s, not %s" % (name, got, expected[name]))
        mgr.shutdown()
        sys.exit(1)
print("portsettings: ok")
sys.stdout.flush()
mgr.shutdown()
