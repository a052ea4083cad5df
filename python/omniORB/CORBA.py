# SPDX-License-Identifier: MIT
"""omniORBpy's module CORBA as Python components use it: Object (the base of the generated
_objref_ classes), is_nil, and the exceptions."""

COMPLETED_YES, COMPLETED_NO, COMPLETED_MAYBE = 0, 1, 2


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
        return omniORB.objrefClass(interface._NP_RepositoryId)(self._obj)


def is_nil(obj):
    """True for None (omniORBpy's nil) and for nil references."""
    return obj is None or (isinstance(obj, Object) and obj._is_nil())
