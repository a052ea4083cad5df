# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CSPEventPort: CSPEventPort, the reading end of CSP channels whose samples are events
of a static FSM (OpenRTM_aist.StaticFSM.Machine, OpenRTM_aist.CSPMachine). bindEvent0(name, handler)
and bindEvent1(name, handler, data) name the handler of the samples of a connection named name, or
whose property fsm_event_name is name (bindEvent1 hands it the sample). read() and readData() answer
the event of the sample they take: calling it runs the handler in the machine."""

import RTC
from OpenRTM_aist import StaticFSM
from OpenRTM_aist.CSPPort import CSPInPort


class _Event(object):
    """A sample turned event: calling it dispatches the handler to the machine and runs it."""

    def __init__(self, fsm, handler, args):
        self._fsm = fsm
        self._handler = handler
        self._args = args

    def __call__(self):
        self._fsm.dispatch(StaticFSM.Event(self._handler, *self._args))
        StaticFSM.Machine.run_event(self._fsm)


class _Unbound(object):
    """The event of a sample no bindEvent names, or of none: calling it only says so."""

    def __init__(self, port, connector):
        self._port = port
        self._connector = connector

    def __call__(self):
        if self._connector:
            self._port._error("no event is bound to connection '%s'" % self._connector)
        else:
            self._port._error("no event has arrived")


class CSPEventPort(CSPInPort):
    def __init__(self, name, fsm=None, manager=None):
        CSPInPort.__init__(self, name, RTC.TimedLong(RTC.Time(0, 0), 0), manager)
        self._fsm = fsm
        self._handlers = {}
        self._value = _Unbound(self, "")

    def bindEvent0(self, name, handler):
        self._handlers[name] = (handler, False)

    def bindEvent1(self, name, handler, data_type):
        self._handlers[name] = (handler, True)

    def _sample(self, taken):
        connector_id, sample = taken
        connector, event_name = self._channel_names.get(connector_id, ("", ""))
        bound = self._handlers.get(event_name) or self._handlers.get(connector)
        if bound is None:
            return _Unbound(self, connector or connector_id)
        handler, with_data = bound
        return _Event(self._fsm, handler, (sample,) if with_data else ())
