#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A user serializer between two Python components of one process: the source's OutPort writes
# RTC.TimedLong, the sink's InPort is RTC.TimedDouble, and the serializer registered under
# "cdr:RTC/TimedLong:RTC/TimedDouble" reads the one as the other for connections whose
# inport.marshaling_type names it; on the OutPort's side, "cdr:RTC/TimedDouble:RTC/TimedLong" writes
# the one as the other for connections whose outport.marshaling_type names it. The sink prints what
# its port and its data listener get; its InPort reads each connection's samples by that connection's
# marshaling type (PyDoubleSource sends plain TimedDouble).

import functools
import sys

import OpenRTM_aist
import RTC
from testspec import component_spec


spec = functools.partial(component_spec, description="Serialized pair")


class LongToDouble(OpenRTM_aist.CORBA_CdrMemoryStream):
    def deserialize(self, cdr, data_type):
        ret, sample = OpenRTM_aist.CORBA_CdrMemoryStream.deserialize(self, cdr, RTC.TimedLong)
        return ret, RTC.TimedDouble(sample.tm, sample.data / 4.0)


class LongAsDouble(OpenRTM_aist.CORBA_CdrMemoryStream):
    """The OutPort's side: writes the source's TimedLong samples as eighths, TimedDouble."""

    def serialize(self, data):
        return OpenRTM_aist.CORBA_CdrMemoryStream.serialize(self, RTC.TimedDouble(data.tm, data.data / 8.0))


class Received(OpenRTM_aist.ConnectorDataListenerT):
    def __call__(self, info, data):
        print("listener got %r" % (data.data,))
        return OpenRTM_aist.ConnectorListenerStatus.NO_CHANGE, data


class PyLongSource(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._data = RTC.TimedLong(RTC.Time(0, 0), 0)
        self._outport = OpenRTM_aist.OutPort("out", self._data)
        self.addOutPort("out", self._outport)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        self._data.data += 1
        self._outport.write()
        return RTC.RTC_OK


class PyDoubleSource(OpenRTM_aist.DataFlowComponentBase):
    """Plain TimedDouble samples, for the sink's second connection."""

    def onInitialize(self):
        self._data = RTC.TimedDouble(RTC.Time(0, 0), 1000.125)
        self._outport = OpenRTM_aist.OutPort("out", self._data)
        self.addOutPort("out", self._outport)
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        self._outport.write()
        return RTC.RTC_OK


class PyDoubleSink(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._inport = OpenRTM_aist.InPort("in", RTC.TimedDouble(RTC.Time(0, 0), 0.0))
        self._inport.addConnectorDataListener(OpenRTM_aist.ConnectorDataListenerType.ON_RECEIVED, Received())
        self.addInPort("in", self._inport)
        return RTC.RTC_OK

    def onActivated(self, ec_id):
        print("sink activated")
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        while self._inport.isNew():
            print("sink got %r" % (self._inport.read().data,))
        return RTC.RTC_OK


def PySerializedInit(manager):
    OpenRTM_aist.SerializerFactories.instance().addSerializer("cdr:RTC/TimedLong:RTC/TimedDouble", LongToDouble,
                                                              RTC.TimedDouble)
    OpenRTM_aist.SerializerFactories.instance().addSerializer("cdr:RTC/TimedDouble:RTC/TimedLong", LongAsDouble,
                                                              RTC.TimedLong)
    for cls in (PyLongSource, PyDoubleSource, PyDoubleSink):
        manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec(cls.__name__)), cls, OpenRTM_aist.Delete)
        manager.createComponent(cls.__name__)


if __name__ == "__main__":
    mgr = OpenRTM_aist.Manager.init(sys.argv)
    mgr.setModuleInitProc(PySerializedInit)
    mgr.activateManager()
    mgr.runManager()
