# SPDX-License-Identifier: MIT
"""OpenRTM-aist-Python's CORBA_CdrMemoryStream: the plain CDR serializer, the base of user serializers
(OpenRTM-aist-Python's Serializer example converts TimedShort to TimedDouble over it)."""

import omniORB
from omniORB import any

from OpenRTM_aist.ByteDataStreamBase import ByteDataStreamBase


class CORBA_CdrMemoryStream(ByteDataStreamBase):
    def __init__(self):
        self._little = True

    def isLittleEndian(self, little_endian):
        self._little = bool(little_endian)

    def serialize(self, data):
        """(SERIALIZE_OK, the CDR bytes of data), or (SERIALIZE_ERROR, None)."""
        try:
            return ByteDataStreamBase.SERIALIZE_OK, omniORB.cdrMarshal(any.to_any(data).typecode(), data,
                                                                      int(self._little))
        except (TypeError, ValueError):
            return ByteDataStreamBase.SERIALIZE_ERROR, None

    def deserialize(self, cdr, data_type):
        """(SERIALIZE_OK, a value of data_type (a class or a value of it) read from cdr), or
        (SERIALIZE_ERROR, data_type)."""
        try:
            return ByteDataStreamBase.SERIALIZE_OK, omniORB.cdrUnmarshal(any.to_any(data_type).typecode(), cdr,
                                                                        int(self._little))
        except (TypeError, ValueError):
            return ByteDataStreamBase.SERIALIZE_ERROR, data_type
