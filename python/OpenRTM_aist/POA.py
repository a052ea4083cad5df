# SPDX-License-Identifier: MIT
"""The little of PortableServer.POA that OpenRTM-aist-Python's components use: turning a component
(the servant) into its object reference. The runtime activates every component itself, so there is
one POA for all of them, as the manager's getPOA() returns it."""


class POA(object):
    def servant_to_reference(self, servant):
        """The object reference of the component servant (an RTC.RTObject)."""
        return servant.getObjRef()

    def servant_to_id(self, servant):
        return servant.getInstanceName().encode()
