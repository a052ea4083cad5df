// SPDX-License-Identifier: MIT
// Copying of data port values; the IDL utility headers specialise it for large sequence types.
#ifndef RTC_DATATYPEUTIL_H
#define RTC_DATATYPEUTIL_H

namespace CORBA_Util
{
/// Makes `data1` a copy of `data2`.
template <class T>
void copyData(T &data1, const T &data2)
{
    data1 = data2;
}
} // namespace CORBA_Util

#endif // RTC_DATATYPEUTIL_H
