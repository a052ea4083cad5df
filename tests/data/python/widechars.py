#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Wide characters and wide strings in Python samples: they survive a round trip in both byte orders
# and are written as omniORB writes and reads them (a wchar as big-endian UTF-16 after its length
# octet, a wstring as big-endian UTF-16). Exits non-zero on the first failure.

import _rtstudio
import OpenRTM_aist
import RTC


def round_trip(value):
    for little in (True, False):
        back = _rtstudio.cdr_decode(value._NP_RepositoryId, _rtstudio.cdr_encode(value, little), little)
        assert back == value, (value, back)


def main():
    wchar = RTC.TimedWChar(RTC.Time(5, 6), u"\u3042")
    round_trip(wchar)
    assert _rtstudio.cdr_encode(wchar).hex() == "0500000006000000023042", _rtstudio.cdr_encode(wchar).hex()
    wstring = RTC.TimedWString(RTC.Time(7, 8), u"h\u3042!")
    round_trip(wstring)
    assert _rtstudio.cdr_encode(wstring).hex() == "070000000800000006000000006830420021"
    # What omniORB writes on a little-endian machine: a byte-order mark, then its own order.
    marked = bytes.fromhex("070000000800000008000000fffe680042302100")
    assert _rtstudio.cdr_decode("IDL:RTC/TimedWString:1.0", marked).data == u"h\u3042!"
    assert OpenRTM_aist.instantiateDataType(RTC.TimedWChar).data == u"\x00"
    print("widechars: ok")


if __name__ == "__main__":
    main()
