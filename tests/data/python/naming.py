#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A name server's contexts walked from Python as omniORBpy programs walk them (AutoTest's
# rtc_handle.py): CorbaNaming._rootContext, CosNaming's list() with its BindingIterator, resolve() of
# names made by omniORB.URI, narrowing to CosNaming.NamingContext and RTC.RTObject; then the
# configuration of the component named on the command line read and changed through its reference
# (anys in NVLists), and omniidl's <File>_idl modules. Prints each binding found and "naming: ok".
#
#   naming.py NAME_SERVER COMPONENT_NAME PARAMETER VALUE

import sys

import RTC  # first: the other IDL modules import once RTC has
import SDOPackage
from OpenRTM_aist.CorbaNaming import *  # noqa: F401,F403 (CorbaNaming, CosNaming and CORBA, as OpenRTM-aist-Python's)
from omniORB import URI, any

import BasicDataType_idl  # omniidl's module of an IDL file of the runtime
from ExtendedDataTypes_idl import *  # noqa: E402,F401,F403


def check(condition, what):
    if not condition:
        print("naming: FAILED:", what)
        sys.exit(1)


def names():
    name = URI.stringToName("host.host_cxt/Con\\/sole.rtc")
    check([(c.id, c.kind) for c in name] == [("host", "host_cxt"), ("Con/sole", "rtc")], "stringToName")
    check(URI.nameToString(name) == "host.host_cxt/Con\\/sole.rtc", "nameToString")
    try:
        URI.stringToName("a//b")
        check(False, "an empty component is refused")
    except CosNaming.NamingContext.InvalidName:
        pass
    check(URI.addrAndNameToURI("localhost:2809", "a.b/c") == "corbaname:localhost:2809#a.b/c", "addrAndNameToURI")


def walk(context, parent, found, how_many=2):
    """Every binding under context: its path and whether it is an object or a context."""
    bindings, iterator = context.list(how_many)
    while True:
        for binding in bindings:
            path = (parent + "/" if parent else "") + URI.nameToString(binding.binding_name)
            if binding.binding_type == CosNaming.nobject:
                found[path] = context.resolve(binding.binding_name)
            else:
                inner = context.resolve(binding.binding_name)._narrow(CosNaming.NamingContext)
                walk(inner, path, found, how_many)
        if iterator is None:
            return
        more, bindings = iterator.next_n(how_many)
        if not more:
            iterator.destroy()
            return


def configure(component, parameter, value):
    configuration = component.get_configuration()
    sets = configuration.get_configuration_sets()
    default = [s for s in sets if s.id == "default"][0]
    values = {nv.name: any.from_any(nv.value) for nv in default.configuration_data}
    print("naming: %s was %s" % (parameter, values[parameter]))
    values[parameter] = value
    default.configuration_data = [SDOPackage.NameValue(k, any.to_any(v)) for k, v in sorted(values.items())]
    check(configuration.set_configuration_set_values(default), "set_configuration_set_values")
    check(configuration.activate_configuration_set("default"), "activate_configuration_set")


def main():
    name_server, wanted, parameter, value = sys.argv[1:5]
    names()
    naming = CorbaNaming(CORBA.ORB_init(sys.argv), name_server)
    root = naming._rootContext
    check(isinstance(root, CosNaming._objref_NamingContext), "the root context is a NamingContext")
    found = {}
    walk(root, "", found)
    for path in sorted(found):
        component = found[path]._narrow(RTC.RTObject)
        print("naming: object", path, "RTC" if component is not None else "")
    paths = [path for path in found if path.endswith("/" + wanted)]
    check(len(paths) == 1, "%s listed once" % wanted)
    component = root.resolve(URI.stringToName(paths[0]))._narrow(RTC.RTObject)
    check(component.get_component_profile().instance_name == wanted.split(".")[0], "the component resolved")
    configure(component, parameter, value)
    check(BasicDataType_idl._0_RTC is RTC and "RTC" in BasicDataType_idl._exported_modules, "BasicDataType_idl")
    print("naming: ok")


if __name__ == "__main__":
    main()
