// SPDX-License-Identifier: MIT
// An InPort as the receiving end of in-process delivery.
#ifndef RTC_DIRECTINPORTBASE_H
#define RTC_DIRECTINPORTBASE_H

#include <rtm/DirectPortBase.h>

namespace RTC {
/// What an OutPort of the same process calls to hand a sample of @p DataType to an InPort.
template<class DataType> class DirectInPortBase : public DirectPortBase
{
public:
    ~DirectInPortBase() override = default;
    virtual bool isNew() = 0;
    virtual bool isEmpty() = 0;
    virtual void write(DataType &data) = 0;
};
} // namespace RTC

#endif // RTC_DIRECTINPORTBASE_H
