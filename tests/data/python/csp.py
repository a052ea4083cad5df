#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# CSP channels (OpenRTM_aist.CSPOutPort, CSPInPort, CSPManager, CSPEventPort, CSPMachine) between
# components of one manager, connected as rtc.conf's preconnect connects them: a write waits for a
# reader when the InPort's buffer.length is 0 and fills the buffer otherwise, reads wait for a writer,
# both give up after channel_timeout, select names the port that can go on, samples are copies, and
# an event port runs the machine's handler of the connection's fsm_event_name. Connections a CSP port
# cannot make are refused. Exits non-zero on the first failure; prints "csp: ok" at the end.

import functools
import sys
import threading
import time

import OpenRTM_aist
import OpenRTM_aist.CSPEventPort as CSPEventPort
import OpenRTM_aist.CSPMachine as CSPMachine
import OpenRTM_aist.StaticFSM as StaticFSM
import RTC
from testspec import component_spec

made = {}
trace = []


def check(condition, what):
    if not condition:
        print("csp: FAILED:", what)
        sys.stdout.flush()
        OpenRTM_aist.Manager.instance().shutdown()
        sys.exit(1)


spec = functools.partial(component_spec, description="CSP test")


@StaticFSM.FSM_TOPSTATE
class Door(StaticFSM.Link):
    def onInit(self):
        self.set_state(StaticFSM.State(Closed))

    def open(self):
        pass

    def close(self):
        pass

    def paint(self, colour):
        trace.append("paint %d" % colour.data)


@StaticFSM.FSM_SUBSTATE(Door)
class Closed(StaticFSM.Link):
    def onEntry(self):
        trace.append("closed")

    def open(self):
        self.set_state(StaticFSM.State(Opened))


@StaticFSM.FSM_SUBSTATE(Door)
class Opened(StaticFSM.Link):
    def onEntry(self):
        trace.append("opened")

    def close(self):
        self.set_state(StaticFSM.State(Closed))


class CspSource(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.value = RTC.TimedLong(RTC.Time(0, 0), 0)
        self.manager = OpenRTM_aist.CSPManager()
        self.out = OpenRTM_aist.CSPOutPort("out", self.value, self.manager)
        self.toBuffered = OpenRTM_aist.CSPOutPort("tobuffered", self.value)
        self.spare = OpenRTM_aist.CSPOutPort("spare", self.value)
        self.events = {name: OpenRTM_aist.CSPOutPort(name, self.value) for name in ("open", "close", "paint")}
        self.addOutPort("out", self.out)
        self.addOutPort("tobuffered", self.toBuffered)
        self.addOutPort("spare", self.spare)
        for name, port in self.events.items():
            self.addOutPort(name, port)
        made["source"] = self
        return RTC.RTC_OK


class CspSink(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.manager = OpenRTM_aist.CSPManager()
        self.inport = OpenRTM_aist.CSPInPort("in", RTC.TimedLong(RTC.Time(0, 0), 0), self.manager)
        self.buffered = OpenRTM_aist.CSPInPort("buffered", RTC.TimedLong(RTC.Time(0, 0), 0))
        self.plain = OpenRTM_aist.InPort("plain", RTC.TimedLong(RTC.Time(0, 0), 0))
        self.marked = OpenRTM_aist.CSPInPort("marked", RTC.TimedLong(RTC.Time(0, 0), 0))
        self.addInPort("in", self.inport)
        self.addInPort("buffered", self.buffered)
        self.addInPort("plain", self.plain)
        self.addInPort("marked", self.marked)
        made["sink"] = self
        return RTC.RTC_OK


class CspDoor(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self.manager = OpenRTM_aist.CSPManager()
        self.fsm = CSPMachine.CSPMachine(Door, self, self.manager)
        self.event = CSPEventPort.CSPEventPort("event", self.fsm, self.manager)
        self.addInPort("event", self.event)
        self.event.bindEvent0("open", Door.open)
        self.event.bindEvent0("close", Door.close)
        self.event.bindEvent1("paint", Door.paint, RTC.TimedLong(RTC.Time(0, 0), 0))
        made["door"] = self
        return RTC.RTC_OK


def later(seconds, action):
    """Runs action in a thread after seconds; the thread keeps what action answered."""
    result = []
    thread = threading.Thread(target=lambda: (time.sleep(seconds), result.append(action())))
    thread.start()
    return thread, result


def connectorNames(port):
    return sorted(profile.name for profile in port.get_connector_profiles())


def init(manager):
    for cls in (CspSource, CspSink, CspDoor):
        manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec(cls.__name__)), cls, OpenRTM_aist.Delete)
        manager.createComponent(cls.__name__)


channel = "dataflow_type=duplex&interface_type=csp_channel"
preconnect = ", ".join([
    "CspSource0.out?port=CspSink0.in&" + channel,
    "CspSource0.tobuffered?port=CspSink0.buffered&" + channel,
    "CspSource0.open?port=CspDoor0.event&fsm_event_name=open&" + channel,
    "CspSource0.close?port=CspDoor0.event&fsm_event_name=close&" + channel,
    "CspSource0.paint?port=CspDoor0.event&fsm_event_name=paint&" + channel,
    # A saved system's connector carries the process mark of the program that made it: not this one's.
    "CspSource0.spare?port=CspSink0.marked&csp_channel.process=1-0&" + channel,
    # Refused: a CSP port takes no corba_cdr connection, a plain InPort no CSP channel.
    "CspSource0.out?port=CspSink0.plain&dataflow_type=push&interface_type=corba_cdr",
    "CspSource0.tobuffered?port=CspSink0.plain&" + channel,
])
mgr = OpenRTM_aist.Manager.init([sys.argv[0],
                                  "-o", "naming.enable: NO",
                                  "-o", "corba.master_manager:",
                                  "-o", "logger.enable: NO",
                                  "-o", "manager.components.preconnect: " + preconnect,
                                  "-o", "port.inport.in.buffer.length: 0",
                                  "-o", "port.inport.buffered.buffer.length: 2",
                                  "-o", "port.outport.dataport.channel_timeout: 2",
                                  "-o", "port.inport.dataport.channel_timeout: 2"])
mgr.setModuleInitProc(init)
mgr.activateManager()
mgr.runManager(True)

source, sink, door = made["source"], made["sink"], made["door"]
check(len(sink.inport.get_connector_profiles()) == 1, "the rendezvous channel is connected")
check(len(door.event.get_connector_profiles()) == 3, "three event channels are connected")
check(sink.plain.get_connector_profiles() == [], "a plain InPort refuses CSP channels and CSP ports corba_cdr")
check(len(source.out.get_connector_profiles()) == 1, "the refused connection left the CSP port alone")
check(len(sink.marked.get_connector_profiles()) == 1, "a process mark of an earlier connection is dropped")
check(source.spare.write(RTC.TimedLong(RTC.Time(0, 0), 4)) and sink.marked.read().data == 4, "through it")

# Rendezvous (buffer.length 0): the write waits until the read takes the sample, and the sample is a copy.
source.value.data = 7
started = time.monotonic()
reader, got = later(0.2, sink.inport.read)
check(source.out.write(), "a write with a reader coming succeeds")
waited = time.monotonic() - started
source.value.data = 8
reader.join()
check(waited >= 0.15, "the write waited for the reader (%.3f s)" % waited)
check(got[0].data == 7, "the reader took the sample written, not the variable changed since")

# The reader waits for a writer.
writer, wrote = later(0.2, lambda: source.out.write(RTC.TimedLong(RTC.Time(0, 0), 21)))
check(sink.inport.read().data == 21, "a read waits for the writer")
writer.join()
check(wrote == [True], "the write the reader took succeeds")

# Nobody on the other end: both give up after channel_timeout.
started = time.monotonic()
check(source.out.write() is False, "a write nobody reads fails")
check(1.9 <= time.monotonic() - started < 10, "after channel_timeout")
check(sink.inport.read() is None, "a read nobody writes answers None")

# A buffer of two: two writes go through at once, the third waits for a read; FIFO.
for value in (1, 2):
    started = time.monotonic()
    check(source.toBuffered.write(RTC.TimedLong(RTC.Time(0, 0), value)), "write %d into the buffer" % value)
    check(time.monotonic() - started < 0.3, "write %d did not wait" % value)
reader, got = later(0.2, sink.buffered.read)
check(source.toBuffered.write(RTC.TimedLong(RTC.Time(0, 0), 3)), "a write into a full buffer waits for room")
reader.join()
check([got[0].data, sink.buffered.read().data, sink.buffered.read().data] == [1, 2, 3], "samples in order")

# select: nothing ready, then the InPort with a writer waiting, then the OutPort with a reader waiting.
started = time.monotonic()
check(sink.manager.select(0.2) == (False, None, None), "select with nothing to do")
check(time.monotonic() - started >= 0.15, "select waited its timeout")
writer, wrote = later(0.1, lambda: source.out.write(RTC.TimedLong(RTC.Time(0, 0), 5)))
ret, outport, inport = sink.manager.select(3)
check(ret and outport is None and inport is sink.inport, "select names the InPort a writer waits on")
check(inport.readData().data == 5, "readData takes the waiting sample")
writer.join()
check(wrote == [True], "the selected read completed the write")
reader, got = later(0.1, sink.inport.read)
ret, outport, inport = source.manager.select(3)
check(ret and outport is source.out and inport is None, "select names the OutPort a reader waits on")
source.value.data = 9
check(outport.writeData(), "writeData hands the sample over")
reader.join()
check(got[0].data == 9, "the reader got the sample writeData wrote")

# A reader selecting on a rendezvous channel takes what a writer hands over.
selector, selected = later(0, lambda: (sink.manager.select(3)[2], sink.inport.readData().data))
check(source.out.write(RTC.TimedLong(RTC.Time(0, 0), 11)), "a write to a selecting reader succeeds")
selector.join()
check(selected == [(sink.inport, 11)], "the selecting reader gets it")

# Events: each connection's fsm_event_name names the handler, run by the machine.
check(trace == ["closed"], "the machine starts closed: %s" % trace)
for name, value in (("open", 0), ("paint", 3), ("close", 0)):
    source.value.data = value
    writer, wrote = later(0, source.events[name].write)
    check(door.fsm.run_event(3) is door.event, "run_event handled the %s event" % name)
    writer.join()
check(trace == ["closed", "opened", "paint 3", "closed"], "events ran in the machine: %s" % trace)

# Disconnected: the port has no channel left and a write fails at once.
for profile in source.out.get_connector_profiles():
    sink.inport.disconnect(profile.connector_id)
started = time.monotonic()
check(source.out.write() is False and time.monotonic() - started < 0.3, "a write without channels fails at once")

print("csp: ok")
sys.stdout.flush()
mgr.shutdown()
