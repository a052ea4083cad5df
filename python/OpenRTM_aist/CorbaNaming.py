# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CorbaNaming: a name server's names resolved to references, as OpenRTM-aist-Python's
programs that drive components resolve them (ExtTrigger's Connector.py)."""

from omniORB import CORBA


class CorbaNaming(object):
    def __init__(self, orb, name_server=None):
        self._orb = orb
        self._name_server = name_server

    def init(self, name_server):
        self._name_server = name_server

    def resolve(self, name):
        """The reference bound to name ("ConsoleIn0.rtc", "host.host_cxt/ConsoleIn0.rtc") in the name
        server; a CORBA exception when none is."""
        return self._orb.string_to_object("corbaname::%s#%s" % (self._name_server, name))

    resolveStr = resolve

    def getORB(self):
        return self._orb


__all__ = ["CorbaNaming", "CORBA"]
