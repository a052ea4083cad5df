#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The IDL data types as Python classes (omniORBpy's constructors and names) and their CDR form:
# values survive a round trip in both byte orders, the bytes are OpenRTM's, and values that do not
# fit their type are refused with the member named. Exits non-zero on the first failure.

import os
import sys

import _rtstudio
import OpenRTM_aist
import RTC


def round_trip(value):
    for little in (True, False):
        back = _rtstudio.cdr_decode(value._NP_RepositoryId, _rtstudio.cdr_encode(value, little), little)
        assert back == value, (value, back)
        assert type(back) is type(value)


def check_prefix(arguments):
    # With --expect-prefix PREFIX: the packages and the extension were imported from that prefix.
    if "--expect-prefix" in arguments:
        prefix = os.path.realpath(arguments[arguments.index("--expect-prefix") + 1])
        for module in (_rtstudio, OpenRTM_aist, RTC):
            assert os.path.realpath(module.__file__).startswith(prefix + os.sep), module.__file__


def main():
    check_prefix(sys.argv)
    sample = RTC.TimedLong(RTC.Time(1, 2), 42)
    assert sample._NP_RepositoryId == "IDL:RTC/TimedLong:1.0"
    assert _rtstudio.cdr_encode(sample).hex() == "01000000020000002a000000"
    assert _rtstudio.cdr_encode(sample, False).hex() == "00000001000000020000002a"
    round_trip(sample)
    round_trip(RTC.TimedDoubleSeq(RTC.Time(0, 0), [1.5, -2.25, 1e300]))
    round_trip(RTC.TimedOctetSeq(RTC.Time(0, 0), b"\x00\xffabc"))
    round_trip(RTC.TimedString(RTC.Time(3, 4), "text"))
    round_trip(RTC.TimedBooleanSeq(RTC.Time(0, 0), [True, False]))
    round_trip(RTC.TimedPose2D(RTC.Time(0, 0), RTC.Pose2D(RTC.Point2D(1.0, 2.0), 0.5)))
    round_trip(RTC.TimedCharSeq(RTC.Time(0, 0), "ab"))

    assert RTC.RTC_OK._v == 0 and RTC.RTC_ERROR._v == 1 and str(RTC.RTC_OK) == "RTC_OK"
    assert RTC.ReturnCode_t._items[0] == RTC.RTC_OK
    assert repr(sample) == "RTC.TimedLong(tm=RTC.Time(sec=1, nsec=2), data=42)"

    try:
        _rtstudio.cdr_encode(RTC.TimedLong(RTC.Time(0, 0), "x"))
        raise AssertionError("a str in a long was accepted")
    except TypeError as error:
        assert "RTC::TimedLong.data" in str(error), error
    try:
        RTC.TimedLong(RTC.Time(0, 0))
        raise AssertionError("a missing member was accepted")
    except TypeError as error:
        assert "data" in str(error), error

    empty = OpenRTM_aist.instantiateDataType(RTC.TimedPose2D)
    assert empty == RTC.TimedPose2D(RTC.Time(0, 0), RTC.Pose2D(RTC.Point2D(0.0, 0.0), 0.0)), empty
    assert OpenRTM_aist.instantiateDataType(RTC.TimedOctetSeq).data == b""
    assert OpenRTM_aist.instantiateDataType(RTC.TimedString).data == ""

    properties = OpenRTM_aist.Properties(defaults_str=["a", "1", "b.c", "2", ""])
    assert properties.getProperty("b.c") == "2" and properties.getProperty("x", "none") == "none"
    OpenRTM_aist.setTimestamp(sample)
    assert sample.tm.sec > 1
    print("datatypes: ok")


if __name__ == "__main__":
    main()
    sys.exit(0)
