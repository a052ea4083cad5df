# SPDX-License-Identifier: MIT
"""omniORBpy's module PortableServer as servants use it: Servant, the base of the generated
<Module>__POA classes. The runtime calls a servant's methods by the IDL of its interface."""


class Servant(object):
    _NP_RepositoryId = None

    def _this(self):
        """The servant's reference, activating it on the root POA the first time, as omniORBpy's."""
        import _rtstudio
        import omniORB
        ref = self.__dict__.get("_rtstudio_reference")
        if ref is None:
            ref = _rtstudio.activate_servant(self)
            self.__dict__["_rtstudio_reference"] = ref
        return omniORB.objrefClass(self._NP_RepositoryId)(ref)
