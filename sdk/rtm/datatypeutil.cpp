// SPDX-License-Identifier: MIT
#include <rtm/idl/BasicDataTypeUtil.h>
#include <rtm/idl/CameraCommonInterfaceUtil.h>
#include <rtm/idl/InterfaceDataTypesUtil.h>

#include <cstring>

namespace CORBA_Util {

namespace {

// Sequence assignment copies element by element; images and byte payloads are large enough
// that one block copy is worth it.
template<class Octets> void copyOctets(Octets &to, const Octets &from)
{
    to.length(from.length());
    if (from.length() > 0)
        std::memcpy(to.get_buffer(), from.get_buffer(), from.length());
}

} // namespace

template<> void copyData(RTC::TimedOctetSeq &data1, const RTC::TimedOctetSeq &data2)
{
    if (&data1 == &data2)
        return;
    data1.tm = data2.tm;
    copyOctets(data1.data, data2.data);
}

template<> void copyData(RTC::CameraImage &data1, const RTC::CameraImage &data2)
{
    if (&data1 == &data2)
        return;
    data1.tm = data2.tm;
    data1.width = data2.width;
    data1.height = data2.height;
    data1.bpp = data2.bpp;
    data1.format = data2.format;
    data1.fDiv = data2.fDiv;
    copyOctets(data1.pixels, data2.pixels);
}

template<> void copyData(Img::ImageData &data1, const Img::ImageData &data2)
{
    if (&data1 == &data2)
        return;
    data1.width = data2.width;
    data1.height = data2.height;
    data1.format = data2.format;
    copyOctets(data1.raw_data, data2.raw_data);
}

template<> void copyData(Img::CameraImage &data1, const Img::CameraImage &data2)
{
    if (&data1 == &data2)
        return;
    data1.captured_time = data2.captured_time;
    copyData(data1.image, data2.image);
    data1.intrinsic = data2.intrinsic;
    for (int i = 0; i < 16; ++i)
        data1.extrinsic[i / 4][i % 4] = data2.extrinsic[i / 4][i % 4];
}

template<> void copyData(Img::TimedCameraImage &data1, const Img::TimedCameraImage &data2)
{
    if (&data1 == &data2)
        return;
    data1.tm = data2.tm;
    copyData(data1.data, data2.data);
    data1.error_code = data2.error_code;
}

} // namespace CORBA_Util
