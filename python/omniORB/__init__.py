# SPDX-License-Identifier: MIT
"""The part of omniORBpy's module omniORB that generated stub modules and OpenRTM-aist-Python
programs use, over RT Studio's runtime: stub modules written by `rtctl idl --lang python` open
their IDL modules here, hand their IDL text and classes to the runtime (which marshals calls and
values by IDL type), and register their object reference classes."""

import sys
import types

import _rtstudio
import _rtstudio_idl
from _rtstudio_idl import Enum, EnumItem, StructBase

# Stub modules import these names from here, as from omniORBpy.
from omniORB import CORBA, PortableServer  # noqa: E402

_objref_classes = {}


def openModule(name, fname=None):
    """The module object of IDL module `name` (a package once imported, else a plain module)."""
    module = sys.modules.get(name)
    if module is None:
        module = types.ModuleType(name, "IDL module %s" % name)
        sys.modules[name] = module
        parent, _, leaf = name.rpartition(".")
        if parent:
            setattr(openModule(parent, fname), leaf, module)
    return module


def updateModule(name):
    """Called by an IDL module's package as it is imported. The package is already the module
    that openModule() hands the stub modules (Python registers it before running it)."""
    return sys.modules[name]


def loadIdl(file_name, text):
    """Adds a stub module's IDL declarations to the runtime's types."""
    _rtstudio.add_idl(file_name, text)


def registerTypes(classes):
    """The Python classes of a stub module's structs, unions, enums and exceptions, by scoped name."""
    _rtstudio.add_idl_classes(classes)


def cdrMarshal(tc, data, endian=-1):
    """data of the type of CORBA.TypeCode tc as CDR bytes (endian: 1 little, 0 big, -1 this machine's)."""
    return _rtstudio.cdr_marshal(tc._name, data, endian != 0 and (endian == 1 or sys.byteorder == "little"))


def cdrUnmarshal(tc, encapsulation, endian=-1):
    """A value of the type of CORBA.TypeCode tc from CDR bytes (endian as cdrMarshal's)."""
    return _rtstudio.cdr_unmarshal(tc._name, encapsulation, endian != 0 and (endian == 1 or sys.byteorder == "little"))


def registerObjref(repository_id, cls):
    _objref_classes[repository_id] = cls


def objrefClass(repository_id, dynamic=False):
    """The generated _objref_ class of an interface type id; with dynamic, for an interface of the
    runtime's IDL without a generated stub (OpenRTM's RTC.RTObject, …) a class calling its operations
    by name; else CORBA.Object."""
    cls = _objref_classes.get(repository_id)
    if cls is None and dynamic and _rtstudio.knows_interface(repository_id):
        cls = type("_objref_" + repository_id.split(":")[1].split("/")[-1], (_DynamicObject,),
                   {"_NP_RepositoryId": repository_id})
        _objref_classes[repository_id] = cls
    return cls if cls is not None else CORBA.Object


class _DynamicObject(CORBA.Object):
    """A reference to an interface of the runtime's IDL without a generated stub module: its
    operations (and attributes' _get_x / _set_x) are called by name, marshalled by the IDL."""

    def __getattr__(self, name):
        if name.startswith("__") or name in ("_obj", "_NP_RepositoryId"):
            raise AttributeError(name)
        return lambda *args: self._invoke(name, args)


class Union(object):
    """An IDL union as omniORBpy's: U(discriminator, value) or U(member=value); `_d`, `_v`, and
    the member chosen by name."""

    _d_to_m = {}
    _m_to_d = {}
    _def_m = None

    def __init__(self, *args, **kw):
        if len(args) == 2:
            self._d, self._v = args
        elif len(kw) == 1:
            member, value = next(iter(kw.items()))
            if member not in self._m_to_d:
                raise AttributeError(member)
            self._d, self._v = self._m_to_d[member], value
        else:
            raise TypeError("%s takes a discriminator and a value, or one member" % type(self).__name__)

    def _member(self):
        return self._d_to_m.get(self._d, self._def_m)

    def __getattr__(self, name):
        if name in self._m_to_d or name == self._def_m:
            if self.__dict__.get("_d") is not None and self._member() == name:
                return self._v
            raise CORBA.BAD_PARAM(0, CORBA.COMPLETED_NO)
        raise AttributeError(name)

    def __setattr__(self, name, value):
        if name in self._m_to_d:
            self.__dict__["_d"] = self._m_to_d[name]
            self.__dict__["_v"] = value
        else:
            self.__dict__[name] = value

    def __eq__(self, other):
        return type(self) is type(other) and (self._d, self._v) == (other._d, other._v)

    def __ne__(self, other):
        return not self == other

    __hash__ = None

    def __repr__(self):
        return "%s(%r, %r)" % (self._NP_ClassName, self._d, self._v)
