#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# CORBA.Any as omniORBpy's (a TypeCode and a value; omniORB.any.to_any / from_any) in data types:
# SDOPackage.NameValue and NVLists convert to CDR and back with basic values and strings, an Any of
# another type is refused; and OpenRTM_aist.NVUtil makes and reads NVLists. Exits non-zero on the
# first failure.

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
    nvlists()
    print("anys: ok")


if __name__ == "__main__":
    main()
