# SPDX-License-Identifier: MIT
# bench_python's Python sink: FlowSink (flowsink.cpp) written against OpenRTM-aist-Python's API,
# its ON_BUFFER_WRITE listener given each sample decoded; it prints the same line per size.

import sys
import time

import OpenRTM_aist
import RTC

END_OF_SIZE_MARK = -2.0

pyflowsink_spec = ["implementation_id", "PyFlowSink", "type_name", "PyFlowSink",
                   "description", "Measures bench_python's samples", "version", "1.0.0", "vendor", "RTStudioBench",
                   "category", "bench", "activity_type", "DataFlowComponent", "max_instance", "0",
                   "language", "Python", "lang_type", "script", ""]


class FlowListener(OpenRTM_aist.ConnectorDataListenerT):
    def __init__(self, instance):
        self._instance = instance
        self._latencies = []
        self._arrivals = []
        self._bytes = 0

    def __call__(self, info, sample):
        arrival = time.time()
        if len(sample.data) < 2:
            return OpenRTM_aist.ConnectorListenerStatus.NO_CHANGE, sample
        if sample.data[0] == END_OF_SIZE_MARK:
            self._report(int(sample.data[1]))
        elif sample.data[0] >= 0:
            self._latencies.append((arrival - (sample.tm.sec + sample.tm.nsec * 1e-9)) * 1e6)
            self._arrivals.append(arrival)
            self._bytes = len(sample.data) * 8
        return OpenRTM_aist.ConnectorListenerStatus.NO_CHANGE, sample

    def _report(self, elements):
        if not self._latencies:
            return
        ordered = sorted(self._latencies)
        span = self._arrivals[-1] - self._arrivals[0]
        rate = self._bytes * (len(self._arrivals) - 1) / span / (1024.0 * 1024.0) if span > 0 else 0.0
        sys.stdout.write("flow %s %d %d %.1f %.1f %.2f\n" % (self._instance, elements, len(ordered),
                                                          sum(ordered) / len(ordered), ordered[len(ordered) // 2],
                                                          rate))
        sys.stdout.flush()
        self._latencies = []
        self._arrivals = []


class PyFlowSink(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._sample = RTC.TimedDoubleSeq(RTC.Time(0, 0), [])
        self._in = OpenRTM_aist.InPort("in", self._sample)
        self._in.addConnectorDataListener(OpenRTM_aist.ConnectorDataListenerType.ON_BUFFER_WRITE,
                                          FlowListener(self.getInstanceName()))
        self.addInPort("in", self._in)
        return RTC.RTC_OK


def PyFlowSinkInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=pyflowsink_spec), PyFlowSink, OpenRTM_aist.Delete)
