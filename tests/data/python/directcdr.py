#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Values straight between Python objects and CDR give the same bytes and values as through the
# converter (direct=False), for every IDL data type the packages know (zero values) and for values of
# every kind it takes (numbers at their limits, strings, bytes, chars, enums, nested structs, long
# sequences), in both byte orders; a value that does not fit still says why; types it leaves to the
# converter (wide characters, unions) still convert. Exits non-zero on the first failure.

import _rtstudio
import _rtstudio_idl
import RTC


def same(value, what):
    for little in (True, False):
        direct = _rtstudio.cdr_encode(value, little)
        converted = _rtstudio.cdr_encode(value, little, direct=False)
        assert direct == converted, "%s (%s): %r != %r" % (what, little, direct[:64], converted[:64])
        back = _rtstudio.cdr_decode(value._NP_RepositoryId, direct, little)
        back_converted = _rtstudio.cdr_decode(value._NP_RepositoryId, direct, little, direct=False)
        assert _rtstudio.cdr_encode(back, little) == direct, what
        assert _rtstudio.cdr_encode(back_converted, little) == direct, what
        assert type(back) is type(back_converted), what


def every_type():
    count = 0
    for namespace in _rtstudio_idl._scopes.values():
        for cls in list(namespace.values()):
            if not (isinstance(cls, type) and issubclass(cls, _rtstudio_idl.StructBase)):
                continue
            try:
                value = _rtstudio.default_value(cls._NP_RepositoryId)
            except (TypeError, ValueError):
                continue  # what the converter cannot make either (TypeCode members)
            same(value, cls._NP_RepositoryId)
            count += 1
    assert count > 100, count


def kinds():
    stamp = RTC.Time(2 ** 32 - 1, 999999999)
    same(RTC.TimedDoubleSeq(stamp, [0.5 * i for i in range(5000)]), "long double sequence")
    same(RTC.TimedLongSeq(stamp, [-2 ** 31, 2 ** 31 - 1, 0]), "long limits")
    same(RTC.TimedULongSeq(stamp, [0, 2 ** 32 - 1]), "unsigned long limits")
    same(RTC.TimedUShort(stamp, 65535), "unsigned short limit")
    same(RTC.TimedShortSeq(stamp, [-32768, 32767]), "short limits")
    same(RTC.TimedFloat(stamp, 1.25), "float")
    same(RTC.TimedBoolean(stamp, True), "boolean")
    same(RTC.TimedChar(stamp, "x"), "char")
    same(RTC.TimedString(stamp, "h\u00e9llo \u4e16"), "UTF-8 string")
    same(RTC.TimedOctetSeq(stamp, bytes(range(256))), "octets as bytes")
    same(RTC.TimedOctetSeq(stamp, [1, 2, 255]), "octets as a list")
    same(RTC.TimedCharSeq(stamp, "abc"), "chars as a str")
    same(RTC.TimedStringSeq(stamp, ["a", "", "\u00e9"]), "strings")
    same(RTC.TimedPose2D(stamp, RTC.Pose2D(RTC.Point2D(1.0, 2), 0.5)), "nested structs, an int for a double")
    actuator = _rtstudio.default_value("IDL:RTC/Actuator:1.0")
    actuator.status = RTC.ACTUATOR_STATUS_STALLED
    same(actuator, "enum")
    actuator.status = 2
    same(actuator, "enum as its value")
    # Left to the converter: wide characters, unions.
    same(RTC.TimedWChar(stamp, "\u3042"), "wide character")
    same(RTC.TimedWString(stamp, "\u3042!"), "wide string")


def refusals():
    for value, message in ((RTC.TimedShort(RTC.Time(0, 0), 70000), "data"),
                           (RTC.TimedLong(RTC.Time(0, 0), "x"), "data"),
                           (RTC.TimedDoubleSeq(RTC.Time(0, 0), "abc"), "data")):
        try:
            _rtstudio.cdr_encode(value)
            assert False, "%r converted" % (value,)
        except TypeError as error:
            assert message in str(error), error
    truncated = _rtstudio.cdr_encode(RTC.TimedDoubleSeq(RTC.Time(0, 0), [1.0, 2.0]))[:-4]
    try:
        _rtstudio.cdr_decode("IDL:RTC/TimedDoubleSeq:1.0", truncated)
        assert False, "truncated bytes decoded"
    except ValueError as error:
        assert "ends early" in str(error) or "remain" in str(error), error


def main():
    every_type()
    kinds()
    refusals()
    print("directcdr: ok")


if __name__ == "__main__":
    main()
