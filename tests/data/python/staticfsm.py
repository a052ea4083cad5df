#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# OpenRTM_aist.StaticFSM as OpenRTM-aist-Python's static FSM: entry, exit and init actions in order,
# events answered by the nearest state that overrides them, transitions after the handler, events
# dispatched from a handler after the transition, data boxes, deep history; and the helpers such
# components use (StringUtil, TimeValue), and the pyfsm-based names. Exits non-zero on the first failure.

import OpenRTM_aist
import OpenRTM_aist.StaticFSM as StaticFSM
import RTC

trace = []


@StaticFSM.FSM_TOPSTATE
class Top(StaticFSM.Link):
    def onInit(self):
        self.set_state(StaticFSM.State(Running))

    def pause(self):
        pass

    def add(self, amount):
        trace.append("ignored")

    def step(self):
        pass

    class Data:
        def __init__(self):
            self.total = 0


@StaticFSM.deephistory
@StaticFSM.FSM_SUBSTATE(Top)
class Running(StaticFSM.Link):
    def onEntry(self):
        trace.append("enter Running")

    def onExit(self):
        trace.append("exit Running")

    def onInit(self):
        self.set_state(StaticFSM.State(Slow))

    def pause(self):
        self.set_state(StaticFSM.State(Paused))


@StaticFSM.FSM_SUBSTATE(Running)
class Slow(StaticFSM.Link):
    def onEntry(self):
        trace.append("enter Slow")

    def onExit(self):
        trace.append("exit Slow")

    def step(self):
        self.set_state(StaticFSM.State(Fast))
        self.dispatch(StaticFSM.Event(Top.add, 2))


@StaticFSM.FSM_SUBSTATE(Running)
class Fast(StaticFSM.Link):
    def onEntry(self):
        trace.append("enter Fast")

    def add(self, amount):
        self.data(Top).total += amount
        trace.append("add %d" % amount)


@StaticFSM.FSM_SUBSTATE(Top)
class Paused(StaticFSM.Link):
    def onEntry(self):
        trace.append("enter Paused")

    def step(self):
        self.set_state(StaticFSM.State(Running))


def expect(*steps):
    assert trace == list(steps), trace
    del trace[:]


def machine():
    fsm = StaticFSM.Machine(Top, None)
    expect("enter Running", "enter Slow")
    fsm.dispatch(StaticFSM.Event(Top.step))
    expect()  # events wait for run_event()
    fsm.run_event()
    expect("exit Slow", "enter Fast", "add 2")
    fsm.dispatch(StaticFSM.Event(Top.add, 3))
    fsm.dispatch(StaticFSM.Event(Top.pause))
    fsm.run_event()
    expect("add 3", "exit Running", "enter Paused")
    assert fsm.isInstate(Paused) and not fsm.isInstate(Running)
    fsm.dispatch(StaticFSM.Event(Top.add, 1))  # Paused leaves add to Top
    fsm.dispatch(StaticFSM.Event(Top.step))
    fsm.run_event()
    expect("ignored", "enter Running", "enter Fast")  # deep history: back to Fast, no onInit
    assert fsm._box(Top).total == 5
    fsm.shutdown()
    expect("exit Running")


def helpers():
    assert OpenRTM_aist.normalize("  Double ") == "double"
    assert OpenRTM_aist.StringUtil.eraseBlank(" st art\t") == "start"
    assert OpenRTM_aist.StringUtil.stringTo(0, "12") == (True, 12)
    assert OpenRTM_aist.StringUtil.stringTo(0, "x") == (False, 0)
    assert OpenRTM_aist.StringUtil.stringTo([0.0], "1,2.5") == (True, [1.0, 2.5])
    difference = OpenRTM_aist.TimeValue(5, 200) - OpenRTM_aist.TimeValue(3, 900000)
    assert (difference.sec(), difference.usec()) == (1, 100200), str(difference)
    assert abs(difference.toDouble() - 1.1002) < 1e-9
    assert OpenRTM_aist.Time().getTime().sec() > 1600000000
    info = OpenRTM_aist.ConnectorDataListenerT()
    sample = RTC.TimedLong(RTC.Time(0, 0), 4)
    assert info(None, sample, RTC.TimedLong(RTC.Time(0, 0), 0), OpenRTM_aist.PortType.InPortType) is sample


def pyfsm_names():
    # The names of OpenRTM-aist-Python's pyfsm-based variant reach the same machine and port.
    import OpenRTM_aist.EventPort as EventPort
    import OpenRTM_aist.EventPort_pyfsm as EventPortPyfsm
    import OpenRTM_aist.StaticFSM_pyfsm as Pyfsm
    assert Pyfsm.Machine is StaticFSM.Machine and Pyfsm.FSM_SUBSTATE is StaticFSM.FSM_SUBSTATE
    assert EventPortPyfsm.EventInPort is EventPort.EventInPort


def main():
    machine()
    pyfsm_names()
    helpers()
    print("staticfsm: ok")


if __name__ == "__main__":
    main()
