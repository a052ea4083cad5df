# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CorbaConsumer: the far end of a required interface, filled in when the service
port connects. _ptr() is the provider's reference as the interface's generated _objref_ class."""

import _rtstudio
import omniORB


class CorbaConsumer(object):
    def __init__(self, interfaceType=None, consumer=None):
        self._interfaceType = interfaceType
        self._slot = _rtstudio.ConsumerSlot()
        self._object = None

    def _ptr(self, get_ref=False):
        """The provider's reference (or the object given to setObject()), or None while there is none."""
        reference = self._object._obj if self._object is not None else self._slot.reference()
        if reference is None:
            return None
        if self._interfaceType is None:
            return omniORB.CORBA.Object(reference)
        return omniORB.objrefClass(self._interfaceType._NP_RepositoryId, True)(reference)

    def setObject(self, obj):
        """Holds obj (a reference, as a program resolving names gives it) instead of a port's provider."""
        self._object = obj
        return True

    def getObject(self):
        return self._ptr()

    def releaseObject(self):
        self._object = None
        self._slot.releaseObject()
