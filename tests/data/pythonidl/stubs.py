# SPDX-License-Identifier: MIT
# The Python modules rtctl idl writes for Calc.idl: they import as omniORBpy's do, construct values
# with omniORBpy's argument order and names, and values convert to CDR and back by their IDL types.
import sys

import _rtstudio
import PyCalc
import PyCalc__POA
import RTC
from omniORB import CORBA, PortableServer


def check(condition, what):
    if not condition:
        print("stubs: FAILED:", what)
        sys.exit(1)


def name_value(value):
    import SDOPackage
    return SDOPackage.NameValue("n", value)


def round_trip(value):
    return _rtstudio.cdr_decode(value._NP_RepositoryId, _rtstudio.cdr_encode(value))


check(PyCalc.MAX_TERMS == 4 and PyCalc.GREETING == "hello" and PyCalc.STRICT is True and PyCalc.HALF == 0.5,
      "constants")
check(PyCalc.ADD._v == 0 and PyCalc.MULTIPLY._v == 1 and str(PyCalc.MULTIPLY) == "MULTIPLY", "enumerators")
check(PyCalc.Mode._items == [PyCalc.ADD, PyCalc.MULTIPLY] or tuple(PyCalc.Mode._items) == (PyCalc.ADD, PyCalc.MULTIPLY),
      "enum items")

term = PyCalc.Term(2.5, "two and a half")
check((term.value, term.label) == (2.5, "two and a half"), "struct members in declaration order")
check(term._NP_RepositoryId == "IDL:PyCalc/Term:1.0", "repository id")
record = PyCalc.Record(PyCalc.MULTIPLY, [term, PyCalc.Term(-1.0, "")], [1, 2, 3], RTC.Time(5, 6), b"\x00\xff")
back = round_trip(record)
check(back == record, "struct round trip: %r" % (back,))
check(back.mode is PyCalc.MULTIPLY or back.mode == PyCalc.MULTIPLY, "enum member round trip")
check(isinstance(back.terms[0], PyCalc.Term) and back.when.sec == 5 and back.raw == b"\x00\xff", "nested members")

error = PyCalc.TooMany(4, "too many terms")
check(isinstance(error, CORBA.UserException) and (error.limit, error.reason) == (4, "too many terms"), "exception")
check(round_trip(error) == error, "exception round trip")

choice = PyCalc.Choice(number=7)
check(choice._d == 1 and choice._v == 7 and choice.number == 7, "union by member")
check(PyCalc.Choice(2, "text").text == "text", "union by discriminator")

for typedef in (PyCalc.TermList, PyCalc.LongList, PyCalc.Triple):
    try:
        typedef()
        check(False, "a typedef cannot be constructed")
    except RuntimeError:
        pass

# TypeCodes as omniidl's stubs have them, and anys of the stubs' types.
from omniORB import any  # noqa: E402
check(PyCalc._tc_Record.kind() == CORBA.tk_struct and PyCalc._tc_Record.member_type(1) == PyCalc._tc_TermList,
      "struct TypeCode")
check(PyCalc._tc_Triple.kind() == CORBA.tk_alias and PyCalc._tc_Triple.content_type().length() == 3, "array TypeCode")
check(PyCalc._tc_Calculator.id() == "IDL:PyCalc/Calculator:1.0" and PyCalc._tc_TooMany.kind() == CORBA.tk_except,
      "interface and exception TypeCodes")
for value in (any.to_any(record), any.to_any(choice), any.to_any(PyCalc.MULTIPLY), any.to_any(error),
              CORBA.Any(PyCalc._tc_Triple, [1, 2, 3]), CORBA.Any(CORBA.TC_TypeCode, PyCalc._tc_Choice)):
    pair = round_trip(name_value(value))
    check(pair.value == value, "any round trip: %r" % (pair.value,))

check(issubclass(PyCalc__POA.Calculator, PortableServer.Servant), "servant base")
check(issubclass(PyCalc__POA.Scientific, PyCalc__POA.Calculator), "servant inheritance")
check(issubclass(PyCalc._objref_Scientific, PyCalc._objref_Calculator), "object reference inheritance")
for method in ("total", "split", "accumulate", "flip", "later", "_get_name", "_set_name", "_get_calls"):
    check(hasattr(PyCalc._objref_Calculator, method), "operation " + method)
check(not hasattr(PyCalc._objref_Calculator, "_set_calls"), "readonly attribute")
check(PyCalc.Calculator._NP_RepositoryId == "IDL:PyCalc/Calculator:1.0", "interface id")
check(CORBA.is_nil(PyCalc.Calculator._nil), "nil reference")
print("stubs: ok")

# Scopes.idl, compiled with Calc.idl into the same folder.
import _GlobalIDL
import _GlobalIDL__POA
import Outer
import Outer__POA

check(_GlobalIDL.TOP == 3 and _GlobalIDL.GPoint(1).x == 1, "global declarations")
check(issubclass(_GlobalIDL__POA.GlobalThing, PortableServer.Servant), "global servant base")
deep = Outer.Inner.Deep(_GlobalIDL.GPoint(2), 5)
check(round_trip(deep) == deep and deep._NP_RepositoryId == "IDL:Outer/Inner/Deep:1.0", "nested module struct")
check(Outer.Inner.Holder.LIMIT == 9 and Outer.Inner.Holder.Item(4).v == 4, "declarations inside an interface")
check(Outer.FAVOURITE == Outer.GREEN, "enumerator constant")
check(issubclass(Outer__POA.Inner.Holder, _GlobalIDL__POA.GlobalThing), "servant inheritance across modules")
check(issubclass(Outer.Inner._objref_Holder, _GlobalIDL._objref_GlobalThing), "reference inheritance across modules")
print("scopes: ok")
