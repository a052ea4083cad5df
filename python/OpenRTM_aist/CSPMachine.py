# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CSPMachine: a static FSM whose events come through the CSP ports of a CSPManager."""

from OpenRTM_aist import StaticFSM


class CSPMachine(StaticFSM.Machine):
    def __init__(self, TOP, comp, cspmgr):
        StaticFSM.Machine.__init__(self, TOP, comp)
        self._manager = cspmgr

    def getComp(self):
        return self._rtobject

    def init_other(self, other):
        pass

    def equal(self, snapshot):
        pass

    def run_event(self, timeout=10):
        """Waits up to timeout seconds for a port of the manager: runs the event an InPort brings, or
        writes an OutPort's variable; answers the port, or None when none was ready."""
        ret, outport, inport = self._manager.select(timeout)
        if not ret:
            return None
        if inport is not None:
            inport.readData()()
            return inport
        outport.write()
        return outport
