# SPDX-License-Identifier: MIT
# bench_python's Python source: FlowSource (flowsource.cpp) written against OpenRTM-aist-Python's
# API, sending the same samples (see flowprotocol.h).

import time

import OpenRTM_aist
import RTC

SIZES = (1, 1024, 65536)
WARM_UP_SAMPLES = 5
WARM_UP_MARK = -1.0
END_OF_SIZE_MARK = -2.0

pyflowsource_spec = ["implementation_id", "PyFlowSource", "type_name", "PyFlowSource",
                     "description", "Writes bench_python's samples", "version", "1.0.0", "vendor", "RTStudioBench",
                     "category", "bench", "activity_type", "DataFlowComponent", "max_instance", "0",
                     "language", "Python", "lang_type", "script", ""]


def samples_for(elements):
    return 50 if elements > 10000 else 500


class PyFlowSource(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        self._sample = RTC.TimedDoubleSeq(RTC.Time(0, 0), [])
        self._out = OpenRTM_aist.OutPort("out", self._sample)
        self.addOutPort("out", self._out)
        self._sent = True
        return RTC.RTC_OK

    def onActivated(self, ec_id):
        self._sent = False
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        if self._sent:
            return RTC.RTC_OK
        self._sent = True
        for elements in SIZES:
            self._sample.data = [0.0] * max(elements, 2)
            for _ in range(WARM_UP_SAMPLES):
                self._send(WARM_UP_MARK)
            for index in range(samples_for(elements)):
                self._send(float(index))
            self._sample.data = [END_OF_SIZE_MARK, float(elements)]
            self._send(END_OF_SIZE_MARK)
        return RTC.RTC_OK

    def _send(self, first):
        self._sample.data[0] = first
        stamp = time.time()
        self._sample.tm.sec = int(stamp)
        self._sample.tm.nsec = int((stamp - int(stamp)) * 1e9)
        self._out.write()


def PyFlowSourceInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=pyflowsource_spec), PyFlowSource,
                            OpenRTM_aist.Delete)
