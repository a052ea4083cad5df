# SPDX-License-Identifier: MIT
"""The interfaces whose object references the runtime hands to Python (a component's RTC.RTObject,
its RTC.ExecutionContext), named in their IDL modules so that `obj._narrow(RTC.RTObject)` reads as
with omniORBpy: the references carry their operations themselves and _narrow() returns them as they
are. A module that defines these names already keeps its own."""


class Interface(object):
    """An IDL interface as a _narrow() argument: its repository id and name."""

    def __init__(self, repository_id):
        self._NP_RepositoryId = repository_id

    def __repr__(self):
        return "<interface %s>" % self._NP_RepositoryId


class ObjectReference(object):
    """An object reference carried in a data type (RTC.PortProfile's port_ref, …) as its IOR: the type id
    and the tagged profiles, kept to be sent on as they came. A nil reference is None, as in omniORBpy."""

    def __init__(self, type_id, profiles):
        self._NP_RepositoryId = type_id
        self._profiles = list(profiles)

    def __repr__(self):
        return "<object reference %s>" % self._NP_RepositoryId

    def __eq__(self, other):
        return isinstance(other, ObjectReference) and (self._NP_RepositoryId, self._profiles) == (
            other._NP_RepositoryId, other._profiles)

    def __ne__(self, other):
        return not self == other

    __hash__ = None


_REFERENCES = {
    "RTC": ["LightweightRTObject", "RTObject", "DataFlowComponent", "ExecutionContext",
            "ExecutionContextService"],
}


def populate(namespace, module_name):
    """Adds the interfaces of module_name that the runtime's references stand for, and the other
    interfaces its IDL declares (to _narrow() references to, which then call their operations by
    name), unless defined."""
    import _rtstudio
    for name in _REFERENCES.get(module_name, []):
        namespace.setdefault(name, Interface("IDL:omg.org/%s/%s:1.0" % (module_name, name)))
    for name, repository_id in _rtstudio.interface_ids(module_name).items():
        namespace.setdefault(name, Interface(repository_id))
