// SPDX-License-Identifier: MIT
// copyData() for the interface data types whose payload is a large octet sequence.
#ifndef RTC_INTERFACEDATATYPESUTIL_H
#define RTC_INTERFACEDATATYPESUTIL_H

#include <rtm/DataTypeUtil.h>
#include <rtm/idl/InterfaceDataTypesSkel.h>

namespace CORBA_Util
{
/// Copies the image's header fields and its pixels in one block.
template <>
void copyData(RTC::CameraImage &data1, const RTC::CameraImage &data2);
} // namespace CORBA_Util

#endif // RTC_INTERFACEDATATYPESUTIL_H
