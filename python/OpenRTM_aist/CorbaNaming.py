# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CorbaNaming: a name server's names resolved to references, as OpenRTM-aist-Python's
programs that drive components resolve them (ExtTrigger's Connector.py), and its root context
(`_rootContext`, a CosNaming.NamingContext) for those that walk its contexts (AutoTest's
rtc_handle.py). `from OpenRTM_aist.CorbaNaming import *` gives CosNaming too, as OpenRTM-aist-Python's
module does."""

from omniORB import CORBA

try:
    import CosNaming
except ImportError:  # built without omniORB's IDL (omniorb-idl)
    CosNaming = None


class CorbaNaming(object):
    def __init__(self, orb, name_server=None):
        self._orb = orb
        self._name_server = name_server
        self._root = None

    def init(self, name_server):
        self._name_server = name_server
        self._root = None

    @property
    def _rootContext(self):
        """The name server's root naming context, as OpenRTM-aist-Python's CorbaNaming keeps it."""
        if self._root is None:
            if CosNaming is None:
                raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
            obj = self._orb.string_to_object("corbaloc::%s/NameService" % self._name_server)
            self._root = obj._narrow(CosNaming.NamingContext)
        return self._root

    def resolve(self, name):
        """The reference bound to name ("ConsoleIn0.rtc", "host.host_cxt/ConsoleIn0.rtc") in the name
        server; a CORBA exception when none is."""
        return self._orb.string_to_object("corbaname::%s#%s" % (self._name_server, name))

    resolveStr = resolve

    def getORB(self):
        return self._orb

    def getRootContext(self):
        return self._rootContext


__all__ = ["CorbaNaming", "CORBA", "CosNaming"]
