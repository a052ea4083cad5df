# SPDX-License-Identifier: MIT
"""Python classes for OpenRTM's IDL types in omniORBpy's layout (module RTC, RTC.TimedLong,
RTC.RTC_OK, …), made from the IDL files installed with the SDK: a struct is a class whose
constructor takes the members in declaration order, an enum a class with one item per
enumerator, the items and the integer constants live in the enclosing scope. The extension
converts values of these classes to and from CDR by the same IDL."""

import importlib.util
import os
import sys
import types

import _rtstudio


def _idl_directories():
    # The packages live in <prefix>/lib/python3/dist-packages, OpenRTM's IDL in <prefix>/include.
    prefix = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
    return [os.path.join(prefix, "include", "openrtm-2.1", "rtm", "idl")]


def _repository_id(scoped_name):
    return "IDL:" + scoped_name.replace("::", "/") + ":1.0"


def _python_name(scoped_name):
    return scoped_name.replace("::", ".")


class StructBase(object):
    """An IDL struct: members as attributes, set positionally in declaration order."""

    _NP_RepositoryId = None
    _fields = ()

    def __init__(self, *args, **kwargs):
        if len(args) > len(self._fields):
            raise TypeError("%s takes %d members, %d given" % (self._NP_ClassName, len(self._fields), len(args)))
        for name, value in zip(self._fields, args):
            setattr(self, name, value)
        for name, value in kwargs.items():
            if name not in self._fields:
                raise TypeError("%s has no member %s" % (self._NP_ClassName, name))
            setattr(self, name, value)
        missing = [name for name in self._fields if name not in self.__dict__]
        if missing:
            raise TypeError("%s() misses %s" % (self._NP_ClassName, ", ".join(missing)))

    def __repr__(self):
        members = ", ".join("%s=%r" % (name, getattr(self, name, None)) for name in self._fields)
        return "%s(%s)" % (self._NP_ClassName, members)

    def __eq__(self, other):
        return type(self) is type(other) and all(
            getattr(self, name, None) == getattr(other, name, None) for name in self._fields)

    def __ne__(self, other):
        return not self == other

    __hash__ = None


class EnumItem(object):
    """One enumerator: its name in _n and its value in _v, as omniORBpy's items."""

    def __init__(self, name, value, parent_id):
        self._n = name
        self._v = value
        self._parent_id = parent_id

    def __repr__(self):
        return self._n

    __str__ = __repr__

    def __eq__(self, other):
        return isinstance(other, EnumItem) and (self._parent_id, self._v) == (other._parent_id, other._v)

    def __ne__(self, other):
        return not self == other

    def __lt__(self, other):
        return self._v < other._v

    def __hash__(self):
        return hash((self._parent_id, self._v))


class Enum(object):
    """An IDL enum: its items in _items, in declaration order."""

    def __init__(self, repository_id, items):
        self._NP_RepositoryId = repository_id
        self._items = items

    def _item(self, value):
        return self._items[value]


class UnionBase(object):
    """An IDL union as omniORBpy has it: the discriminator in _d, the value in _v, made as
    Numeric(_d, _v) or Numeric(long_value=5); a member's name reads or sets the value of its case."""

    _NP_RepositoryId = None
    _cases = ()  # (member, discriminator values, is default)

    def __init__(self, *args, **kwargs):
        if len(args) == 2 and not kwargs:
            self._d, self._v = args
        elif not args and len(kwargs) == 1:
            name, value = next(iter(kwargs.items()))
            setattr(self, name, value)
        else:
            raise TypeError("%s() takes (_d, _v) or one member=value" % self._NP_ClassName)

    @classmethod
    def _case(cls, name):
        for member, labels, is_default in cls._cases:
            if member == name:
                return labels, is_default
        return None

    def _member(self):
        """The member the discriminator selects (None when no case does)."""
        default = None
        for member, labels, is_default in self._cases:
            if self._d in labels:
                return member
            if is_default:
                default = member
        return default

    def __getattr__(self, name):
        if name.startswith("_") or self._case(name) is None:
            raise AttributeError(name)
        if self._member() != name:
            raise ValueError("%s holds %s, not %s" % (self._NP_ClassName, self._member(), name))
        return self._v

    def __setattr__(self, name, value):
        case = None if name.startswith("_") else self._case(name)
        if case is None:
            object.__setattr__(self, name, value)
            return
        labels, _ = case
        if not labels:
            raise ValueError("%s.%s is the default case: set _d and _v" % (self._NP_ClassName, name))
        object.__setattr__(self, "_d", labels[0])
        object.__setattr__(self, "_v", value)

    def __repr__(self):
        return "%s(_d=%r, _v=%r)" % (self._NP_ClassName, self._d, self._v)

    def __eq__(self, other):
        return type(self) is type(other) and (self._d, self._v) == (other._d, other._v)

    def __ne__(self, other):
        return not self == other

    __hash__ = None


def _scope(scopes, scoped_name):
    """The namespace dict of the scope enclosing scoped_name (nested scopes become module objects)."""
    parts = scoped_name.split("::")[:-1]
    namespace = scopes.setdefault(parts[0], {})
    for depth in range(1, len(parts)):
        inner = namespace.get(parts[depth])
        if inner is None:
            inner = types.ModuleType("::".join(parts[:depth + 1]))
            namespace[parts[depth]] = inner
        namespace = inner.__dict__ if isinstance(inner, types.ModuleType) else inner.__dict__
    return namespace


def _make_types():
    description = _rtstudio.load_idl(_idl_directories())
    _description["files"] = description["files"]
    scopes = {}
    classes = {}
    for scoped_name, members in description["structs"].items():
        leaf = scoped_name.split("::")[-1]
        cls = type(leaf, (StructBase,), {
            "_NP_RepositoryId": _repository_id(scoped_name),
            "_NP_ClassName": _python_name(scoped_name),
            "_fields": tuple(members),
        })
        classes[scoped_name] = cls
        _scope(scopes, scoped_name)[leaf] = cls
    for scoped_name, names in description["enums"].items():
        repository_id = _repository_id(scoped_name)
        enum = Enum(repository_id, [EnumItem(name, value, repository_id) for value, name in enumerate(names)])
        classes[scoped_name] = enum
        scope = _scope(scopes, scoped_name)
        scope[scoped_name.split("::")[-1]] = enum
        for item in enum._items:
            scope[item._n] = item
    for scoped_name, (enum_name, _, cases) in description["unions"].items():
        leaf = scoped_name.split("::")[-1]
        enum = classes.get(enum_name)
        cls = type(leaf, (UnionBase,), {
            "_NP_RepositoryId": _repository_id(scoped_name),
            "_NP_ClassName": _python_name(scoped_name),
            "_cases": tuple((member, [enum._items[[item._n for item in enum._items].index(label)]
                                      if enum else label for label in labels], is_default)
                            for member, labels, is_default in cases),
        })
        classes[scoped_name] = cls
        _scope(scopes, scoped_name)[leaf] = cls
    for scoped_name, value in description["consts"].items():
        _scope(scopes, scoped_name)[scoped_name.split("::")[-1]] = value
    from omniORB import CORBA
    for scoped_name in description["typecodes"]:
        _scope(scopes, scoped_name)["_tc_" + scoped_name.split("::")[-1]] = CORBA.TypeCode(scoped_name)
    _rtstudio.set_idl_classes(classes)
    return scopes


_description = {}
_scopes = _make_types()


def _register_modules():
    """Makes the IDL modules without a package of their own here (Img, JARA_ARM, …) importable
    as omniORBpy lays them out (`import Img`, `Img.TimedCameraImage`), once the types are made."""
    for name, namespace in _scopes.items():
        if name in sys.modules or importlib.util.find_spec(name) is not None:
            continue
        module = types.ModuleType(name, "IDL module %s" % name)
        module.__dict__.update(namespace)
        # Its interfaces, to _narrow() references to (OpenRTM.ExtTrigExecutionContextService, …).
        import _rtstudio_interfaces
        _rtstudio_interfaces.populate(module.__dict__, name)
        sys.modules[name] = module


_register_modules()


def _file_module(base, modules):
    """omniidl's module <base>_idl of an IDL file: omniORB, CORBA and PortableServer, and _0_<Module>
    for each module the file declares in (found as it is first asked for)."""
    import omniORB
    module = types.ModuleType(base + "_idl", "Python stubs of %s.idl" % base)
    module.__dict__.update({"omniORB": omniORB, "CORBA": omniORB.CORBA, "PortableServer": omniORB.PortableServer,
                            "_exported_modules": tuple(modules), "__all__": ["omniORB", "CORBA", "PortableServer"]})

    def module_getattr(name):
        if name.startswith("_0_") and name[3:] in modules:
            return importlib.import_module(name[3:])
        raise AttributeError(name)

    module.__getattr__ = module_getattr
    return module


class _FileModuleFinder(object):
    """Finds omniidl's <File>_idl modules of the runtime's IDL files (BasicDataType_idl, …) on import."""

    @staticmethod
    def find_spec(name, path=None, target=None):
        if path is not None or not name.endswith("_idl") or name[:-4] not in _description["files"]:
            return None
        return importlib.util.spec_from_loader(name, _FileModuleFinder)

    @staticmethod
    def create_module(spec):
        base = spec.name[:-4]
        return _file_module(base, _description["files"][base])

    @staticmethod
    def exec_module(module):
        pass


sys.meta_path.append(_FileModuleFinder)


def populate(namespace, module_name):
    """Puts the types, enumerators and constants of IDL module module_name into namespace."""
    namespace.update(_scopes.get(module_name, {}))
