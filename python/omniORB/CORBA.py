# SPDX-License-Identifier: MIT
"""omniORBpy's module CORBA as Python components use it: Object (the base of the generated
_objref_ classes), is_nil, and the exceptions."""

COMPLETED_YES, COMPLETED_NO, COMPLETED_MAYBE = 0, 1, 2
TRUE, FALSE = True, False


class Exception(Exception):  # noqa: A001 (CORBA.Exception, as omniORBpy names it)
    """The base of CORBA's exceptions."""


class UserException(Exception):
    """The base of the exceptions IDL declares; generated classes set their members."""

    def __init__(self, *args):
        Exception.__init__(self, *args)

    def __eq__(self, other):
        fields = getattr(self, "_fields", ())
        return type(self) is type(other) and all(getattr(self, f) == getattr(other, f) for f in fields)

    __hash__ = Exception.__hash__

    def __repr__(self):
        fields = getattr(self, "_fields", ())
        return "%s(%s)" % (getattr(self, "_NP_ClassName", type(self).__name__),
                           ", ".join("%s=%r" % (f, getattr(self, f, None)) for f in fields))

    __str__ = __repr__


class SystemException(Exception):
    def __init__(self, minor=0, completed=COMPLETED_NO):
        Exception.__init__(self, minor, completed)
        self.minor = minor
        self.completed = completed

    def __str__(self):
        return "CORBA.%s(minor=%#x, completed=%d)" % (type(self).__name__, self.minor, self.completed)


# The system exceptions by the names omniORB gives them.
for _name in ("UNKNOWN", "BAD_PARAM", "NO_MEMORY", "IMP_LIMIT", "COMM_FAILURE", "INV_OBJREF", "NO_PERMISSION",
              "INTERNAL", "MARSHAL", "INITIALIZE", "NO_IMPLEMENT", "BAD_TYPECODE", "BAD_OPERATION",
              "NO_RESOURCES", "NO_RESPONSE", "PERSIST_STORE", "BAD_INV_ORDER", "TRANSIENT", "FREE_MEM",
              "INV_IDENT", "INV_FLAG", "INTF_REPOS", "BAD_CONTEXT", "OBJ_ADAPTER", "DATA_CONVERSION",
              "OBJECT_NOT_EXIST", "TRANSACTION_REQUIRED", "TRANSACTION_ROLLEDBACK", "INVALID_TRANSACTION",
              "INV_POLICY", "CODESET_INCOMPATIBLE", "REBIND", "TIMEOUT", "TRANSACTION_UNAVAILABLE",
              "TRANSACTION_MODE", "BAD_QOS"):
    globals()[_name] = type(_name, (SystemException,), {})
del _name


class Object(object):
    """An object reference: generated _objref_<I> classes call through the runtime with _invoke."""

    _NP_RepositoryId = "IDL:omg.org/CORBA/Object:1.0"
    _nil = None

    def __init__(self, obj):
        self._obj = obj

    def _invoke(self, operation, args):
        return self._obj.invoke(self._NP_RepositoryId, operation, args)

    def _is_a(self, repository_id):
        return self._obj.is_a(repository_id)

    def _non_existent(self):
        return self._obj.non_existent()

    def _is_nil(self):
        return self._obj.is_nil()

    def _narrow(self, interface):
        import omniORB
        if not self._obj.is_a(interface._NP_RepositoryId):
            return None
        return omniORB.objrefClass(interface._NP_RepositoryId, True)(self._obj)


# CORBA's TCKind numbers.
tk_null, tk_void, tk_short, tk_long, tk_ushort, tk_ulong, tk_float, tk_double, tk_boolean, tk_char, tk_octet, \
    tk_any, tk_TypeCode, tk_Principal, tk_objref, tk_struct, tk_union, tk_enum, tk_string, tk_sequence, tk_array, \
    tk_alias, tk_except, tk_longlong, tk_ulonglong, tk_longdouble, tk_wchar, tk_wstring = range(28)
_KINDS = {"null": tk_null, "void": tk_void, "short": tk_short, "long": tk_long, "unsigned short": tk_ushort,
          "unsigned long": tk_ulong, "float": tk_float, "double": tk_double, "boolean": tk_boolean, "char": tk_char,
          "octet": tk_octet, "any": tk_any, "TypeCode": tk_TypeCode, "string": tk_string,
          "long long": tk_longlong, "unsigned long long": tk_ulonglong, "wchar": tk_wchar, "wstring": tk_wstring,
          "Object": tk_objref}


class TypeCode(object):
    """A TypeCode: the IDL type it describes, named as the runtime names types ("long", "string",
    "RTC::Time", "sequence<long>", "long[3]"); TypeCode("IDL:RTC/Time:1.0") names a declared type by its
    repository id, as omniORBpy's constructor does. Its parameters come from the runtime's IDL."""

    def __init__(self, name):
        if name.startswith("IDL:"):
            import _rtstudio
            scoped = _rtstudio.scoped_name_of(name)
            if scoped.startswith("IDL:") or not scoped:
                raise BAD_PARAM(0, COMPLETED_NO)
            name = scoped
        self._name = name

    def _info(self):
        import _rtstudio
        try:
            return _rtstudio.typecode_info(self._name)
        except ValueError:
            raise BAD_TYPECODE(0, COMPLETED_NO)

    def kind(self):
        if self._name in _KINDS:
            return _KINDS[self._name]
        return self._info()["kind"]

    def _parameter(self, key, kinds):
        if self.kind() not in kinds:
            raise TypeCode.BadKind()
        return self._info()[key]

    def id(self):
        if self._name == "Object":
            return "IDL:omg.org/CORBA/Object:1.0"
        return self._parameter("id", (tk_objref, tk_struct, tk_union, tk_enum, tk_alias, tk_except))

    def name(self):
        if self._name == "Object":
            return "Object"
        return self._parameter("name", (tk_objref, tk_struct, tk_union, tk_enum, tk_alias, tk_except))

    def member_count(self):
        return len(self._parameter("members", (tk_struct, tk_union, tk_enum, tk_except)))

    def member_name(self, index):
        members = self._parameter("members", (tk_struct, tk_union, tk_enum, tk_except))
        if not 0 <= index < len(members):
            raise TypeCode.Bounds()
        return members[index][0]

    def member_type(self, index):
        members = self._parameter("members", (tk_struct, tk_union, tk_except))
        if not 0 <= index < len(members):
            raise TypeCode.Bounds()
        return TypeCode(members[index][1])

    def discriminator_type(self):
        return TypeCode(self._parameter("discriminator", (tk_union,)))

    def content_type(self):
        return TypeCode(self._parameter("content", (tk_sequence, tk_array, tk_alias)))

    def length(self):
        return self._parameter("length", (tk_string, tk_wstring, tk_sequence, tk_array))

    def equal(self, other):
        return isinstance(other, TypeCode) and other._name == self._name

    def equivalent(self, other):
        return self.equal(other) or (isinstance(other, TypeCode) and self._unaliased() == other._unaliased())

    def _unaliased(self):
        code = self
        while code.kind() == tk_alias:
            code = code.content_type()
        return code._name

    __eq__ = equal

    def __ne__(self, other):
        return not self.equal(other)

    def __hash__(self):
        return hash(self._name)

    def __repr__(self):
        return "CORBA.TypeCode(%r)" % self._name

    class BadKind(UserException):
        _NP_RepositoryId = "IDL:omg.org/CORBA/TypeCode/BadKind:1.0"

    class Bounds(UserException):
        _NP_RepositoryId = "IDL:omg.org/CORBA/TypeCode/Bounds:1.0"


TC_null, TC_void, TC_short, TC_long, TC_ushort, TC_ulong, TC_float, TC_double, TC_boolean, TC_char, TC_octet, \
    TC_any, TC_TypeCode, TC_string, TC_longlong, TC_ulonglong, TC_wchar, TC_wstring, TC_Object = (
        TypeCode(name) for name in ("null", "void", "short", "long", "unsigned short", "unsigned long", "float",
                                    "double", "boolean", "char", "octet", "any", "TypeCode", "string", "long long",
                                    "unsigned long long", "wchar", "wstring", "Object"))


class Any(object):
    """omniORBpy's CORBA.Any: a TypeCode and a value of its type."""

    def __init__(self, typecode, value):
        self._t = typecode
        self._v = value

    def typecode(self):
        return self._t

    def value(self):
        return self._v

    def __eq__(self, other):
        return isinstance(other, Any) and self._t == other._t and self._v == other._v

    def __ne__(self, other):
        return not self == other

    __hash__ = None

    def __repr__(self):
        return "CORBA.Any(%r, %r)" % (self._t, self._v)


def _reference(ref):
    """The object reference for the runtime's ref: None when nil, else of the generated _objref_
    class of its type id when its stub module is imported (CORBA.Object otherwise), as omniORBpy's."""
    if ref.is_nil():
        return None
    import _rtstudio
    import omniORB
    return omniORB.objrefClass(_rtstudio.ior_type_id(ref.ior()), True)(ref)


class ORB(object):
    """The process's ORB (the one its manager runs), as omniORBpy's CORBA.ORB."""

    def string_to_object(self, text):
        """The reference named by an IOR, corbaloc: or corbaname: text."""
        import _rtstudio
        return _reference(_rtstudio.string_to_object(text))

    def object_to_string(self, obj):
        return obj._obj.ior() if obj is not None else "IOR:01000000010000000000000000000000"

    def resolve_initial_references(self, identifier):
        """The reference of an initial service (NameService, RootPOA, …)."""
        import _rtstudio
        return _reference(_rtstudio.resolve_initial_references(identifier))

    def shutdown(self, wait_for_completion=True):
        """The manager owns the ORB and shuts it down with itself."""

    def destroy(self):
        """The manager owns the ORB and destroys it with itself."""


_orb = ORB()


def ORB_init(argv=None, orb_identifier="omniORB4"):
    """The process's ORB; its arguments are the manager's (Manager.init(argv) reads -ORB… options)."""
    return _orb


def is_nil(obj):
    """True for None (omniORBpy's nil) and for nil references."""
    return obj is None or (isinstance(obj, Object) and obj._is_nil())
