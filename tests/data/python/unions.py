#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# IDL unions in Python samples as omniORBpy has them (SDOPackage.Numeric(_d, _v),
# Numeric(long_value=5), a member's name reading or setting its case): they survive a round trip
# in both byte orders, as members of structs too, with omniORB's bytes. Exits non-zero on the
# first failure.

import _rtstudio
import OpenRTM_aist
import RTC  # noqa: F401 (makes the IDL modules importable)
import SDOPackage


def round_trip(value):
    for little in (True, False):
        back = _rtstudio.cdr_decode(value._NP_RepositoryId, _rtstudio.cdr_encode(value, little), little)
        assert back == value, (value, back)


def main():
    numeric = SDOPackage.Numeric(long_value=5)
    assert (numeric._d, numeric._v, numeric.long_value) == (SDOPackage.LONG_TYPE, 5, 5)
    assert _rtstudio.cdr_encode(numeric).hex() == "0100000005000000"
    round_trip(numeric)
    assert SDOPackage.Numeric(SDOPackage.FLOAT_TYPE, 0.5) == SDOPackage.Numeric(float_value=0.5)
    try:
        numeric.short_value
        raise AssertionError("the member of another case was read")
    except ValueError:
        pass

    interval = OpenRTM_aist.instantiateDataType(SDOPackage.IntervalType)
    assert interval.step._d == SDOPackage.SHORT_TYPE and interval.step.short_value == 0
    interval.min.double_value = -1.5
    interval.max = SDOPackage.Numeric(long_value=70000)
    interval.step.float_value = 0.25
    interval.max_inclusive = True
    round_trip(interval)
    print("unions: ok")


if __name__ == "__main__":
    main()
