// SPDX-License-Identifier: MIT
// An OutPort as the sending end of in-process pull delivery.
#ifndef RTC_DIRECTOUTPORTBASE_H
#define RTC_DIRECTOUTPORTBASE_H

#include <rtm/DirectPortBase.h>

namespace RTC {
/// What an InPort of the same process calls to take a sample of @p DataType from an OutPort.
template<class DataType> class DirectOutPortBase : public DirectPortBase
{
public:
    ~DirectOutPortBase() override = default;
    virtual void read(DataType &data) = 0;
    virtual bool isNew() = 0;
    virtual bool isEmpty() = 0;
};
} // namespace RTC

#endif // RTC_DIRECTOUTPORTBASE_H
