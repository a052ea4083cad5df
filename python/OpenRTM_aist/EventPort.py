# SPDX-License-Identifier: MIT
"""OpenRTM_aist.EventPort: EventInPort, an InPort of RTC.TimedLong whose samples are events of a
static FSM (OpenRTM_aist.StaticFSM.Machine). bindEvent0(name, handler) / bindEvent1(name, handler,
data) make the samples of a connection named name, or whose property fsm_event_name is name, the
event handler (with the sample as its argument for bindEvent1), dispatched to the machine."""

import RTC
import OpenRTM_aist
from OpenRTM_aist import StaticFSM


class _EventBinder(OpenRTM_aist.ConnectorDataListenerT):
    def __init__(self, fsm, event_name, handler, with_data):
        self._fsm = fsm
        self._event_name = event_name
        self._handler = handler
        self._with_data = with_data

    def __call__(self, info, data):
        if info.properties.getProperty("fsm_event_name") == self._event_name or info.name == self._event_name:
            args = (data,) if self._with_data else ()
            self._fsm.dispatch(StaticFSM.Event(self._handler, *args))
        return OpenRTM_aist.ConnectorListenerStatus.NO_CHANGE, data


class EventInPort(OpenRTM_aist.InPort):
    def __init__(self, name, fsm, buffer=None):
        OpenRTM_aist.InPort.__init__(self, name, RTC.TimedLong(RTC.Time(0, 0), 0))
        self._fsm = fsm

    def bindEvent0(self, name, handler):
        self._bind(name, handler, False)

    def bindEvent1(self, name, handler, data_type):
        self._bind(name, handler, True)

    def _bind(self, name, handler, with_data):
        self.addConnectorDataListener(OpenRTM_aist.ConnectorDataListenerType.ON_RECEIVED,
                                      _EventBinder(self._fsm, name, handler, with_data))
