// SPDX-License-Identifier: MIT
// copyData() for the basic data types whose payload is a large octet sequence.
#ifndef RTC_BASICDATATYPEUTIL_H
#define RTC_BASICDATATYPEUTIL_H

#include <rtm/DataTypeUtil.h>
#include <rtm/idl/BasicDataTypeSkel.h>

namespace CORBA_Util
{
/// Copies the time stamp and the octets in one block.
template <>
void copyData(RTC::TimedOctetSeq &data1, const RTC::TimedOctetSeq &data2);
} // namespace CORBA_Util

#endif // RTC_BASICDATATYPEUTIL_H
