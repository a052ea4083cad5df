#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# CORBA.Any as omniORBpy's (a TypeCode and a value; omniORB.any.to_any / from_any) in data types:
# SDOPackage.NameValue and NVLists convert to CDR and back with basic values, strings, structs,
# enums, unions, sequences, anys and TypeCodes; CORBA.TypeCode values (CORBA.TC_*, RTC._tc_<Type>)
# tell their kind and members, SDOPackage.Parameter carries one, omniORB.cdrMarshal / cdrUnmarshal
# write and read values by TypeCode; an Any of an undeclared type is
# refused; and OpenRTM_aist.NVUtil makes and reads NVLists. Exits non-zero on the first failure.

import _rtstudio
import OpenRTM_aist
import RTC  # noqa: F401 (the IDL modules import once RTC has)
import SDOPackage
from OpenRTM_aist import NVUtil
from omniORB import CORBA, any


def round_trip(value):
    return _rtstudio.cdr_decode(value._NP_RepositoryId, _rtstudio.cdr_encode(value))


def anys():
    assert any.to_any(5).typecode() == CORBA.TC_long and any.to_any(2 ** 40).typecode() == CORBA.TC_longlong
    assert any.to_any(True).typecode().kind() == CORBA.tk_boolean
    assert any.from_any(any.to_any("text")) == "text"
    for value in (any.to_any(-5), any.to_any(2.5), any.to_any("corba_cdr"), any.to_any(True),
                  CORBA.Any(CORBA.TC_wstring, "h\u3042"), CORBA.Any(CORBA.TC_octet, 7), any.to_any(None)):
        pair = SDOPackage.NameValue("n", value)
        back = round_trip(pair)
        assert back.name == "n" and back.value == value, (back.value, value)
    try:
        _rtstudio.cdr_encode(SDOPackage.NameValue("n", 5))
        assert False, "a plain value is no Any"
    except TypeError as error:
        assert "CORBA.Any is needed" in str(error), error


def constructed():
    values = (any.to_any(RTC.Time(1, 2)), any.to_any(RTC.TimedLong(RTC.Time(3, 4), 5)), any.to_any(RTC.RTC_ERROR),
              any.to_any(SDOPackage.Numeric(long_value=7)), any.to_any([1, 2]), any.to_any(["a", 2]),
              any.to_any(b"\x01\x02"), any.to_any(RTC._tc_TimedLong), any.to_any(any.to_any(5)),
              CORBA.Any(SDOPackage._tc_NVList, [SDOPackage.NameValue("k", any.to_any(1.5))]),
              CORBA.Any(CORBA.TypeCode("sequence<RTC::Time>"), [RTC.Time(5, 6)]),
              CORBA.Any(CORBA.TypeCode("IDL:RTC/Point2D:1.0"), RTC.Point2D(0.5, 1.5)))
    for value in values:
        back = round_trip(SDOPackage.NameValue("n", value))
        assert back.value == value, (back.value, value)
    assert any.to_any(RTC.Time(1, 2)).typecode() == RTC._tc_Time
    assert any.to_any(["a", 2]).typecode()._name == "sequence<any>"
    assert any.from_any(any.to_any(RTC.TimedLong(RTC.Time(3, 4), 5))) == {"tm": {"sec": 3, "nsec": 4}, "data": 5}
    assert any.from_any(any.to_any(RTC.Time(3, 4)), keep_structs=True) == RTC.Time(3, 4)
    assert any.from_any(any.to_any(["a", 2])) == ["a", 2]
    try:
        _rtstudio.cdr_encode(SDOPackage.NameValue("n", CORBA.Any(CORBA.TypeCode("Acme::Thing"), 1)))
        assert False, "an undeclared type"
    except TypeError as error:
        assert "type 'Acme::Thing' is not declared" in str(error), error


def typecodes():
    code = RTC._tc_TimedLong
    assert code.kind() == CORBA.tk_struct and code.id() == "IDL:RTC/TimedLong:1.0" and code.name() == "TimedLong"
    assert code.member_count() == 2 and code.member_name(1) == "data"
    assert code.member_type(0) == RTC._tc_Time and code.member_type(1) == CORBA.TC_long
    assert RTC._tc_ReturnCode_t.kind() == CORBA.tk_enum and RTC._tc_ReturnCode_t.member_name(0) == "RTC_OK"
    assert SDOPackage._tc_NVList.kind() == CORBA.tk_alias
    assert SDOPackage._tc_NVList.content_type().content_type() == SDOPackage._tc_NameValue
    assert SDOPackage._tc_Numeric.kind() == CORBA.tk_union and CORBA.TC_string.kind() == CORBA.tk_string
    assert RTC._tc_RTObject.kind() == CORBA.tk_objref and CORBA.TC_TypeCode.kind() == CORBA.tk_TypeCode
    assert CORBA.TypeCode("IDL:RTC/Time:1.0") == RTC._tc_Time
    assert SDOPackage._tc_NVList.equivalent(CORBA.TypeCode("sequence<SDOPackage::NameValue>"))
    parameter = SDOPackage.Parameter("gain", RTC._tc_TimedDoubleSeq,
                                     SDOPackage.AllowedValues(allowed_enum=SDOPackage.EnumerationType(["a"])))
    back = round_trip(parameter)
    assert back.type == RTC._tc_TimedDoubleSeq and back.allowed_values.allowed_enum.enumerated_values == ["a"]


def cdr():
    import omniORB
    sample = RTC.TimedShort(RTC.Time(1, 2), -3)
    data = omniORB.cdrMarshal(RTC._tc_TimedShort, sample, 1)
    assert data == _rtstudio.cdr_encode(sample), data
    assert omniORB.cdrUnmarshal(RTC._tc_TimedShort, data, 1) == sample
    big = omniORB.cdrMarshal(CORBA.TypeCode("sequence<long>"), [1, -2], 0)
    assert big == b"\0\0\0\2\0\0\0\1\xff\xff\xff\xfe", big
    assert omniORB.cdrUnmarshal(CORBA.TypeCode("sequence<long>"), big, 0) == [1, -2]


def nvlists():
    nv = [NVUtil.newNV("dataport.interface_type", "corba_cdr"), NVUtil.newNV("count", 3)]
    assert NVUtil.find_index(nv, "count") == 1 and NVUtil.find_index(nv, "none") == -1
    assert NVUtil.find(nv, "count") == 3 and NVUtil.isString(nv, "dataport.interface_type")
    assert NVUtil.isStringValue(nv, "dataport.interface_type", "corba_cdr")
    assert NVUtil.toString(nv, "dataport.interface_type") == "corba_cdr" and NVUtil.toString(nv, "count") == ""
    assert NVUtil.appendStringValue(nv, "dataport.interface_type", "shared_memory")
    assert NVUtil.toString(nv, "dataport.interface_type") == "corba_cdr,shared_memory"
    assert not NVUtil.appendStringValue(nv, "count", "x")
    OpenRTM_aist.CORBA_SeqUtil.push_back(nv, NVUtil.newNV("x", "y"))
    prop = NVUtil.toProperties(nv)
    assert prop.getProperty("x") == "y" and prop.getProperty("count") == ""
    assert round_trip(SDOPackage.NameValue("l", any.to_any("v"))).value.value() == "v"


def main():
    anys()
    constructed()
    typecodes()
    cdr()
    nvlists()
    print("anys: ok")


if __name__ == "__main__":
    main()
