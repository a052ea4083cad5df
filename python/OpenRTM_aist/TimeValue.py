# SPDX-License-Identifier: MIT
"""OpenRTM_aist.TimeValue (seconds and microseconds, with arithmetic) and OpenRTM_aist.Time, whose
getTime() is the current time as a TimeValue, as OpenRTM-aist-Python's components measure."""

import time

_USEC_PER_SEC = 1000000


class TimeValue(object):
    def __init__(self, sec=0, usec=0):
        if isinstance(sec, float) and usec == 0:
            sec, usec = divmod(round(sec * _USEC_PER_SEC), _USEC_PER_SEC)
        self._sec = int(sec)
        self._usec = int(usec)
        self.normalize()

    def sec(self):
        return self._sec

    def usec(self):
        return self._usec

    def normalize(self):
        """Keeps usec within a second, with the sign of the whole value in sec."""
        self._sec, self._usec = divmod(self._sec * _USEC_PER_SEC + self._usec, _USEC_PER_SEC)
        return self

    def toDouble(self):
        return self._sec + self._usec / float(_USEC_PER_SEC)

    def __sub__(self, other):
        return TimeValue(self._sec - other.sec(), self._usec - other.usec())

    def __add__(self, other):
        return TimeValue(self._sec + other.sec(), self._usec + other.usec())

    def __float__(self):
        return self.toDouble()

    def __str__(self):
        return "%d.%06d" % (self._sec, self._usec)


class Time(object):
    """The clock: getTime() is now."""

    def getTime(self):
        now = time.time()
        return TimeValue(int(now), int((now - int(now)) * _USEC_PER_SEC))
