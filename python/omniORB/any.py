# SPDX-License-Identifier: MIT
"""omniORBpy's module omniORB.any: Python values to and from CORBA.Any."""

from omniORB import CORBA


def _type_name(repository_id):
    import _rtstudio
    name = _rtstudio.scoped_name_of(repository_id)
    if not name or name.startswith("IDL:"):
        raise CORBA.BAD_PARAM(0, CORBA.COMPLETED_NO)
    return name


def _typecode_of(data):
    """The TypeCode to_any gives data (see to_any)."""
    if data is None:
        return CORBA.TC_null
    if isinstance(data, bool):
        return CORBA.TC_boolean
    if isinstance(data, int):
        return CORBA.TC_long if -2 ** 31 <= data < 2 ** 31 else CORBA.TC_longlong
    if isinstance(data, float):
        return CORBA.TC_double
    if isinstance(data, str):
        return CORBA.TC_string
    if isinstance(data, (bytes, bytearray)):
        return CORBA.TypeCode("sequence<octet>")
    if isinstance(data, CORBA.Any):
        return CORBA.TC_any
    if isinstance(data, CORBA.TypeCode):
        return CORBA.TC_TypeCode
    if isinstance(data, (list, tuple)):
        return _sequence_typecode(data)
    # Values of IDL types: structs, unions and exceptions by their class, enum items by their enum.
    repository_id = getattr(data, "_parent_id", None) or getattr(data, "_NP_RepositoryId", None)
    if repository_id is None:
        raise CORBA.BAD_PARAM(0, CORBA.COMPLETED_NO)
    return CORBA.TypeCode(_type_name(repository_id))


def _sequence_typecode(items):
    """A sequence of the items' common type, or of anys when they differ (as omniORBpy's)."""
    codes = {_typecode_of(item)._name for item in items}
    element = codes.pop() if len(codes) == 1 else "any"
    return CORBA.TypeCode("sequence<%s>" % element)


def to_any(data):
    """A CORBA.Any of data: None, bool, int (long, or long long when larger), float (double), str,
    bytes (sequence<octet>), a value of an IDL type (its type), a CORBA.Any, a CORBA.TypeCode, or a
    list (a sequence of its items' type, or of anys when they differ)."""
    code = _typecode_of(data)
    if isinstance(data, (list, tuple)) and code._name == "sequence<any>":
        data = [to_any(item) for item in data]
    elif isinstance(data, tuple):
        data = list(data)
    return CORBA.Any(code, data)


def _plain(value):
    """value with structs as dictionaries of their members, the rest kept."""
    if isinstance(value, CORBA.Any):
        return from_any(value)
    if isinstance(value, list):
        return [_plain(item) for item in value]
    fields = getattr(type(value), "_fields", None)
    if fields is not None and not isinstance(value, CORBA.Exception):
        return {name: _plain(getattr(value, name)) for name in fields}
    return value


def from_any(any_, keep_structs=False):
    """The Python value an Any holds: structs as dictionaries of their members, unless keep_structs,
    and the anys it holds as their values."""
    value = any_.value()
    return _plain(value) if not keep_structs else value
