# SPDX-License-Identifier: MIT
"""OpenRTM-aist-Python's serializers: ByteDataStreamBase (their base, with its result codes) and
SerializerFactories, where modules register a serializer class under a marshaling type name and a
data type ("cdr:RTC/TimedShort:RTC/TimedDouble" for RTC.TimedDouble). A connection whose
`inport.marshaling_type` names one has its InPort's samples read by it."""


class ByteDataStreamBase(object):
    SERIALIZE_OK, SERIALIZE_ERROR, SERIALIZE_NOTFOUND, SERIALIZE_NOT_SUPPORT_ENDIAN = range(4)

    def init(self, prop):
        pass

    def isLittleEndian(self, little_endian):
        pass

    def serialize(self, data):
        return ByteDataStreamBase.SERIALIZE_NOTFOUND, None

    def deserialize(self, cdr, data_type):
        return ByteDataStreamBase.SERIALIZE_NOTFOUND, data_type


def _type_id(data_type):
    """The repository id of a data type given as its class or a value of it."""
    return getattr(data_type, "_NP_RepositoryId", None)


class SerializerFactories(object):
    """The serializer classes, by marshaling type name and data type."""

    _instance = None

    def __init__(self):
        self._classes = {}

    @classmethod
    def instance(cls):
        if cls._instance is None:
            cls._instance = cls()
        return cls._instance

    def addSerializer(self, marshalingtype, serializer, datatype):
        self._classes[(marshalingtype, _type_id(datatype))] = serializer

    def removeSerializer(self, marshalingtype, datatype):
        return self._classes.pop((marshalingtype, _type_id(datatype)), None) is not None

    def hasSerializer(self, marshalingtype, datatype):
        return (marshalingtype, _type_id(datatype)) in self._classes

    def createSerializer(self, marshalingtype, datatype):
        """A new serializer of marshalingtype for datatype; None when none is registered."""
        serializer = self._classes.get((marshalingtype, _type_id(datatype)))
        return serializer() if serializer is not None else None

    def getSerializerList(self, datatype):
        return [name for name, type_id in self._classes if type_id == _type_id(datatype)]
