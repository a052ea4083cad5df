# SPDX-License-Identifier: MIT
"""OpenRTM_aist.NVUtil: NVLists (lists of SDOPackage.NameValue, whose values are CORBA.Any) as
OpenRTM-aist-Python's helpers make and read them."""

import SDOPackage
from omniORB import CORBA, any


def newNV(name, value):
    """A NameValue of name holding value (a Python value, or a CORBA.Any as it is)."""
    return SDOPackage.NameValue(name, value if isinstance(value, CORBA.Any) else any.to_any(value))


def find_index(nv, name):
    """The index of name in the NVList nv; -1 when it has none."""
    for index, item in enumerate(nv):
        if item.name == name:
            return index
    return -1


def find(nv, name):
    """The Python value of name in nv; None when it has none."""
    index = find_index(nv, name)
    return any.from_any(nv[index].value) if index >= 0 else None


def isString(nv, name):
    index = find_index(nv, name)
    return index >= 0 and isinstance(any.from_any(nv[index].value), str)


def isStringValue(nv, name, value):
    return isString(nv, name) and find(nv, name) == value


def toString(nv, name=None):
    """The string value of name (empty when it has none or holds no string); without name, every
    name=value line."""
    if name is None:
        return "".join("%s: %s\n" % (item.name, any.from_any(item.value)) for item in nv)
    value = find(nv, name)
    return value if isinstance(value, str) else ""


def appendStringValue(nv, name, value):
    """Adds value to name's comma-separated string (or name with value); False when name holds no string."""
    index = find_index(nv, name)
    if index < 0:
        nv.append(newNV(name, value))
        return True
    current = any.from_any(nv[index].value)
    if not isinstance(current, str):
        return False
    if value not in [part.strip() for part in current.split(",")]:
        nv[index] = newNV(name, current + "," + value if current else value)
    return True


def append(dest, src):
    """Adds the NameValues of src to dest."""
    dest.extend(src)


def copyFromProperties(nv, prop):
    """nv becomes the leaves of the Properties prop, each as a string."""
    del nv[:]
    for key in prop.propertyNames():
        nv.append(newNV(key, prop.getProperty(key)))


def copyToProperties(prop, nvlist):
    """Sets each NameValue of nvlist holding a string in the Properties prop."""
    for item in nvlist:
        value = any.from_any(item.value)
        if isinstance(value, str):
            prop.setProperty(item.name, value)


def toProperties(nv):
    import OpenRTM_aist
    prop = OpenRTM_aist.Properties()
    copyToProperties(prop, nv)
    return prop


def dump(nv):
    print(toString(nv), end="")
