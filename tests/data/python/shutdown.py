#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Manager.shutdown() from the program's main thread returns once every component has been
# finalized, so a program may end right after it: a component whose onExecute ran in its execution
# context's thread and whose onFinalize takes a while is finalized when shutdown() returns, and the
# interpreter then ends without the runtime's threads aborting the process. Exits non-zero on the
# first failure; prints "shutdown: ok" at the end.

import functools
import sys
import threading
import time

import OpenRTM_aist
import RTC
from testspec import component_spec

made = {}
spec = functools.partial(component_spec, description="Shutdown test")


class Slow(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.executed = threading.Event()
        self.finalized = False
        made["slow"] = self
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        self.executed.set()
        return RTC.RTC_OK

    def onFinalize(self):
        time.sleep(0.5)
        self.finalized = True
        return RTC.RTC_OK


def init(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec("Slow")), Slow, OpenRTM_aist.Delete)
    manager.createComponent("Slow")


mgr = OpenRTM_aist.Manager.init([sys.argv[0], "-o", "naming.enable: NO", "-o", "corba.master_manager:",
                                 "-o", "logger.enable: NO", "-o", "exec_cxt.periodic.rate: 100",
                                 "-o", "manager.components.preactivation: Slow0"])
mgr.setModuleInitProc(init)
mgr.activateManager()
mgr.runManager(True)

slow = made["slow"]
if not slow.executed.wait(10):
    print("shutdown: FAILED: the component was not executed")
    sys.exit(1)
mgr.shutdown()
if not slow.finalized:
    print("shutdown: FAILED: shutdown() returned before onFinalize had")
    sys.exit(1)
print("shutdown: ok")
sys.stdout.flush()
