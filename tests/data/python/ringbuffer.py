#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# OpenRTM_aist.RingBuffer as OpenRTM-aist-Python's: values in order, the oldest dropped when full,
# read(list) filling the list and answering a status, length(n) emptying it; and the ports take
# one as their third argument. Exits non-zero on the first failure.

import OpenRTM_aist
import RTC
from OpenRTM_aist import BufferStatus


def main():
    buffer = OpenRTM_aist.RingBuffer(3)
    assert buffer.length() == 3 and buffer.empty() and buffer.writable() == 3
    for value in (1, 2, 3, 4):
        assert buffer.write(value) == BufferStatus.BUFFER_OK
    assert buffer.full() and buffer.readable() == 3
    assert buffer.read() == 2  # 1 was overwritten
    out = [None]
    assert buffer.read(out) == BufferStatus.BUFFER_OK and out == [3]
    assert buffer.read() == 4 and buffer.read() is None
    assert buffer.read(out) == BufferStatus.BUFFER_EMPTY
    buffer.write(5)
    assert buffer.length(5) == BufferStatus.BUFFER_OK and buffer.empty() and buffer.length() == 5
    assert buffer.length(0) == BufferStatus.NOT_SUPPORTED
    value = RTC.TimedLong(RTC.Time(0, 0), 0)
    OpenRTM_aist.InPort("in", value, OpenRTM_aist.RingBuffer(8))
    OpenRTM_aist.OutPort("out", value, OpenRTM_aist.RingBuffer(8))
    print("ringbuffer: ok")


if __name__ == "__main__":
    main()
