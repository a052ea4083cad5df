#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# OpenRTM-aist-Python's serializers: OpenRTM_aist.CORBA_CdrMemoryStream writes and reads plain CDR in
# either byte order, and OpenRTM_aist.SerializerFactories keeps user serializers by marshaling type
# and data type, as the Serializer example registers and the InPorts of its connections use them.
# Exits non-zero on the first failure.

import _rtstudio
import OpenRTM_aist
import RTC


class ShortToDouble(OpenRTM_aist.CORBA_CdrMemoryStream):
    def deserialize(self, cdr, data_type):
        ret, short = OpenRTM_aist.CORBA_CdrMemoryStream.deserialize(self, cdr, RTC.TimedShort)
        return ret, RTC.TimedDouble(short.tm, float(short.data))


def main():
    stream = OpenRTM_aist.CORBA_CdrMemoryStream()
    sample = RTC.TimedShort(RTC.Time(1, 2), -7)
    ret, cdr = stream.serialize(sample)
    assert ret == OpenRTM_aist.ByteDataStreamBase.SERIALIZE_OK and cdr == _rtstudio.cdr_encode(sample), (ret, cdr)
    assert stream.deserialize(cdr, RTC.TimedShort) == (OpenRTM_aist.ByteDataStreamBase.SERIALIZE_OK, sample)
    stream.isLittleEndian(False)
    ret, big = stream.serialize(sample)
    assert big == _rtstudio.cdr_encode(sample, little_endian=False) and stream.deserialize(big, sample)[1] == sample
    assert stream.deserialize(b"\x01", RTC.TimedShort)[0] == OpenRTM_aist.ByteDataStreamBase.SERIALIZE_ERROR

    factories = OpenRTM_aist.SerializerFactories.instance()
    assert factories is OpenRTM_aist.SerializerFactories.instance()
    name = "cdr:RTC/TimedShort:RTC/TimedDouble"
    factories.addSerializer(name, ShortToDouble, RTC.TimedDouble)
    assert factories.createSerializer(name, RTC.TimedShort) is None
    serializer = factories.createSerializer(name, RTC.TimedDouble(RTC.Time(0, 0), 0.0))
    assert isinstance(serializer, ShortToDouble) and factories.getSerializerList(RTC.TimedDouble) == [name]
    ret, converted = serializer.deserialize(cdr, RTC.TimedDouble)
    assert ret == OpenRTM_aist.ByteDataStreamBase.SERIALIZE_OK and converted == RTC.TimedDouble(RTC.Time(1, 2), -7.0)
    assert factories.removeSerializer(name, RTC.TimedDouble) and not factories.hasSerializer(name, RTC.TimedDouble)
    print("serializers: ok")


if __name__ == "__main__":
    main()
