# SPDX-License-Identifier: MIT
"""omniORBpy's module omniORB.any: Python values to and from CORBA.Any (basic types and strings)."""

from omniORB import CORBA


def to_any(data):
    """A CORBA.Any of data: None, bool, int (long, or long long when larger), float (double) or str."""
    if data is None:
        return CORBA.Any(CORBA.TC_null, None)
    if isinstance(data, bool):
        return CORBA.Any(CORBA.TC_boolean, data)
    if isinstance(data, int):
        return CORBA.Any(CORBA.TC_long if -2 ** 31 <= data < 2 ** 31 else CORBA.TC_longlong, data)
    if isinstance(data, float):
        return CORBA.Any(CORBA.TC_double, data)
    if isinstance(data, str):
        return CORBA.Any(CORBA.TC_string, data)
    raise CORBA.BAD_PARAM(0, CORBA.COMPLETED_NO)


def from_any(any_, keep_structs=False):
    """The Python value an Any holds."""
    return any_.value()
