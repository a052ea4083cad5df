# SPDX-License-Identifier: MIT
"""omniORBpy's module PortableServer as servants use it: Servant, the base of the generated
<Module>__POA classes. The runtime calls a servant's methods by the IDL of its interface."""


class Servant(object):
    _NP_RepositoryId = None
