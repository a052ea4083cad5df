# SPDX-License-Identifier: MIT
"""OpenRTM-aist-Python's RingBuffer: a buffer of a fixed number of values for a component's own use.

Ports accept one as OpenRTM-aist-Python's do; their connections keep buffers of their own, sized by the
connector's properties.
"""

import threading

import OpenRTM_aist.BufferStatus as BufferStatus


class RingBuffer:
    def __init__(self, length=8):
        self._lock = threading.Lock()
        self._values = [None] * max(1, int(length))
        self._read = 0
        self._count = 0

    def length(self, n=None):
        """The capacity; with n, makes it n (the values kept are dropped)."""
        if n is None:
            return len(self._values)
        if int(n) < 1:
            return BufferStatus.NOT_SUPPORTED
        with self._lock:
            self._values = [None] * int(n)
            self._read = 0
            self._count = 0
        return BufferStatus.BUFFER_OK

    def reset(self):
        with self._lock:
            self._read = 0
            self._count = 0
        return BufferStatus.BUFFER_OK

    def write(self, value, sec=-1, nsec=0):
        """Appends value; a full buffer drops its oldest value (OpenRTM's overwrite policy)."""
        with self._lock:
            size = len(self._values)
            self._values[(self._read + self._count) % size] = value
            if self._count == size:
                self._read = (self._read + 1) % size
            else:
                self._count += 1
        return BufferStatus.BUFFER_OK

    def read(self, value=None, sec=-1, nsec=0):
        """The oldest value, removed; with a list as value, it is put into value[0] and the status
        returned, as OpenRTM-aist-Python's read(value) does."""
        with self._lock:
            if self._count == 0:
                return BufferStatus.BUFFER_EMPTY if isinstance(value, list) else None
            result = self._values[self._read]
            self._read = (self._read + 1) % len(self._values)
            self._count -= 1
        if isinstance(value, list):
            value[:1] = [result]
            return BufferStatus.BUFFER_OK
        return result

    def readable(self):
        return self._count

    def writable(self):
        return len(self._values) - self._count

    def empty(self):
        return self._count == 0

    def full(self):
        return self._count == len(self._values)
