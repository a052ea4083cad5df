# SPDX-License-Identifier: MIT
"""OpenRTM-aist-Python's CSP channels: CSPOutPort, CSPInPort and CSPManager.

A CSP channel is a connection of dataport.interface_type csp_channel and dataflow_type duplex between
a CSPOutPort and a CSPInPort of one process. write() hands a sample to an InPort that can take it
(room in its buffer, or a reader waiting when its buffer.length is 0) or waits until a reader takes
it; read() takes a buffered sample or one a writer offers, or waits for one. Both give up after the
port's channel_timeout (seconds, 10 unless the port's properties say otherwise) and then answer False
or None. A CSPManager's select(timeout) waits up to timeout seconds until one of its ports can read or
write without waiting and names it; readData() and writeData() then do that.

The runtime connects the ports (it checks that both are in this process) and tells each port of its
connections; the samples go from port to port here, as copies.
"""

import collections
import copy
import sys
import threading
import time

import RTC
import _rtstudio
import OpenRTM_aist

# One lock for every channel of the process: a transfer changes both ends, and a select watches many.
_cond = threading.Condition(threading.RLock())
# Connector id -> {"in": port, "out": port} while the ends hear of a connection.
_pending_ends = {}


class _EndListener(object):
    """Pairs the two ends of a channel by connector id as each port hears of it (ON_CONNECT), and parts
    them on ON_DISCONNECT."""

    def __init__(self, port, connect):
        self._port = port
        self._connect = connect

    def __call__(self, info):
        with _cond:
            if self._connect:
                self._port._channel_names[info.id] = (info.name,
                                                      info.properties.getProperty("fsm_event_name", ""))
                ends = _pending_ends.setdefault(info.id, {})
                ends[self._port._end] = self._port
                if "in" in ends and "out" in ends:
                    ends["in"]._peers[info.id] = ends["out"]
                    ends["out"]._peers[info.id] = ends["in"]
                    del _pending_ends[info.id]
            else:
                peer = self._port._peers.pop(info.id, None)
                if peer is not None:
                    peer._peers.pop(info.id, None)
                self._port._channel_names.pop(info.id, None)
                _pending_ends.pop(info.id, None)
            _cond.notify_all()
        return OpenRTM_aist.ConnectorListenerStatus.NO_CHANGE


class _ChannelEnd(object):
    """What the CSP ports share: their settings, their peers and their manager."""

    def _join_channels(self, end, manager, any_data_type):
        self._end = end
        self._peers = collections.OrderedDict()
        # Connector id -> (connector name, its fsm_event_name)
        self._channel_names = {}
        self._timeout = 10.0
        self._rtcout = None
        self._manager = None
        self._setCspChannel(any_data_type)
        self.addConnectorListener(OpenRTM_aist.ConnectorListenerType.ON_CONNECT, _EndListener(self, True))
        self.addConnectorListener(OpenRTM_aist.ConnectorListenerType.ON_DISCONNECT, _EndListener(self, False))
        if manager is not None:
            self.setManager(manager)

    def _configure(self, properties, rtcout):
        """Takes the port's properties when the component adds the port."""
        self._rtcout = rtcout
        timeout = properties.getProperty("channel_timeout", "10")
        try:
            self._timeout = float(timeout)
        except ValueError:
            self._error("channel_timeout '%s' is not a number of seconds; 10 is used" % timeout)

    def _error(self, message):
        text = "%s: %s" % (self.name(), message)
        if self._rtcout is not None:
            self._rtcout.RTC_ERROR(text)
        else:
            sys.stderr.write(text + "\n")

    def setManager(self, manager):
        self._manager = manager
        manager._add(self)

    def releaseManager(self):
        self._manager = None

    def setSyncMode(self, mode):
        self._syncmode = bool(mode)

    def getSyncMode(self):
        return self._syncmode


class CSPInPort(_rtstudio.InPort, _ChannelEnd):
    """The reading end of CSP channels. Its buffer holds buffer.length samples (8 unless the port's
    properties say otherwise); with 0, a writer waits until a reader takes its sample."""

    def __init__(self, name, value, manager=None):
        _rtstudio.InPort.__init__(self, name, value)
        self._value = value
        self._buffer = collections.deque()
        self._capacity = 8
        self._readers = 0
        self._syncmode = False
        self._OnRead = None
        self._join_channels("in", manager, True)

    def _configure(self, properties, rtcout):
        _ChannelEnd._configure(self, properties, rtcout)
        length = properties.getProperty("buffer.length", "8")
        try:
            self._capacity = max(0, int(length))
        except ValueError:
            self._error("buffer.length '%s' is not a number; 8 is used" % length)
        self._syncmode = OpenRTM_aist.toBool(properties.getProperty("csp.sync_wait", "NO"), "YES", "NO", False)

    # --- under _cond ---

    def _accepts(self):
        """True when a writer may hand a sample over now."""
        if self._capacity > 0:
            return len(self._buffer) < self._capacity
        selecting = 1 if self._manager is not None and self._manager._waiting else 0
        return self._readers + selecting > len(self._buffer)

    def _ready(self):
        return bool(self._buffer) or any(peer._offer is not None for peer in self._peers.values())

    def _take(self):
        """The oldest sample buffered or offered as (connector id, sample); None when there is none."""
        if self._buffer:
            taken = self._buffer.popleft()
            _cond.notify_all()
            return taken
        for connector_id, peer in self._peers.items():
            if peer._offer is not None:
                sample = peer._offer[0]
                peer._offer = None
                _cond.notify_all()
                return connector_id, sample
        return None

    def _sample(self, taken):
        return taken[1]

    # --- OpenRTM-aist-Python's methods ---

    def setOnRead(self, on_read):
        self._OnRead = on_read

    def isNew(self):
        with _cond:
            return self._ready()

    def isEmpty(self):
        return not self.isNew()

    def select(self):
        with _cond:
            return self._ready()

    reselect = select

    def read(self):
        """Waits up to channel_timeout seconds for a sample; None when none came."""
        if self._OnRead is not None:
            self._OnRead()
        with _cond:
            if not self._peers:
                return None
            self._readers += 1
            _cond.notify_all()
            try:
                deadline = time.monotonic() + self._timeout
                while True:
                    taken = self._take()
                    if taken is not None:
                        return self._sample(taken)
                    remaining = deadline - time.monotonic()
                    if remaining <= 0:
                        self._error("read timeout: no sample within %g s" % self._timeout)
                        return None
                    _cond.wait(remaining)
            finally:
                self._readers -= 1

    def readData(self):
        """The sample select() found (without waiting); the last one when there is none now."""
        if self._OnRead is not None:
            self._OnRead()
        with _cond:
            taken = self._take()
        if taken is None:
            return self._value
        self._value = self._sample(taken)
        return self._value


class CSPOutPort(_rtstudio.OutPort, _ChannelEnd):
    """The writing end of CSP channels."""

    def __init__(self, name, value, manager=None):
        _rtstudio.OutPort.__init__(self, name, value)
        self._value = value
        self._offer = None
        self._syncmode = True
        self._OnWrite = None
        self._OnWriteConvert = None
        self._join_channels("out", manager, False)

    def _configure(self, properties, rtcout):
        _ChannelEnd._configure(self, properties, rtcout)
        self._syncmode = OpenRTM_aist.toBool(properties.getProperty("csp.sync_wait", "YES"), "YES", "NO", True)

    # --- under _cond ---

    def _ready(self):
        return self._offer is None and any(peer._accepts() for peer in self._peers.values())

    def _deliver(self, sample):
        for connector_id, peer in self._peers.items():
            if peer._accepts():
                peer._buffer.append((connector_id, sample))
                _cond.notify_all()
                return True
        return False

    # --- OpenRTM-aist-Python's methods ---

    def setOnWrite(self, on_write):
        self._OnWrite = on_write

    def setOnWriteConvert(self, on_wconvert):
        self._OnWriteConvert = on_wconvert

    def _prepare(self, value):
        if value is None:
            value = self._value
        if self._OnWrite is not None:
            self._OnWrite(value)
        if self._OnWriteConvert is not None:
            value = self._OnWriteConvert(value)
        return copy.deepcopy(value)

    def select(self):
        with _cond:
            return self._ready()

    reselect = select

    def write(self, value=None):
        """Hands value (the port's variable when None) to a reader, waiting up to channel_timeout
        seconds for one; False when none took it."""
        sample = self._prepare(value)
        with _cond:
            if not self._peers:
                return False
            if self._deliver(sample):
                return True
            box = [sample]
            self._offer = box
            _cond.notify_all()
            deadline = time.monotonic() + self._timeout
            while True:
                if self._offer is not box:
                    return True
                if self._deliver(sample):
                    self._offer = None
                    return True
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    self._offer = None
                    self._error("write timeout: no reader within %g s" % self._timeout)
                    return False
                _cond.wait(remaining)

    def writeData(self, value=None):
        """Writes to the reader select() found; waits as write() does when it is gone meanwhile."""
        sample = self._prepare(value)
        with _cond:
            if self._deliver(sample):
                return True
        return self.write(sample)


class CSPManager(object):
    """Watches CSP ports for select(); a port joins by naming the manager when it is made."""

    def __init__(self):
        self._inports = []
        self._outports = []
        self._waiting = False

    def _add(self, port):
        ports = self._inports if port._end == "in" else self._outports
        if port not in ports:
            ports.append(port)

    def addInPort(self, port):
        port.setManager(self)

    def addOutPort(self, port):
        port.setManager(self)

    def removeInPort(self, port):
        self._inports.remove(port)
        port.releaseManager()

    def removeOutPort(self, port):
        self._outports.remove(port)
        port.releaseManager()

    def reset(self):
        for port in self._inports + self._outports:
            port.releaseManager()
        self._inports = []
        self._outports = []

    def _ordered(self):
        # As OpenRTM-aist-Python's: ports without sync wait first, InPorts before OutPorts.
        ports = self._inports + self._outports
        return [p for p in ports if not p.getSyncMode()] + [p for p in ports if p.getSyncMode()]

    def select(self, timeout):
        """(True, outport, None) or (True, None, inport) for a port that can write or read now,
        waiting up to timeout seconds (none when negative); (False, None, None) when none could."""
        with _cond:
            self._waiting = True
            _cond.notify_all()
            try:
                deadline = time.monotonic() + max(0.0, float(timeout))
                while True:
                    for port in self._ordered():
                        if port._ready():
                            return (True, None, port) if port._end == "in" else (True, port, None)
                    remaining = deadline - time.monotonic()
                    if timeout < 0 or remaining <= 0:
                        return False, None, None
                    _cond.wait(remaining)
            finally:
                self._waiting = False
