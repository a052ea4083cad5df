// SPDX-License-Identifier: MIT
// The sending side's view of an InPort: where a push connection puts samples.
#ifndef RTC_INPORTCONSUMER_H
#define RTC_INPORTCONSUMER_H

#include <coil/Factory.h>
#include <coil/Properties.h>
#include <rtm/ByteData.h>
#include <rtm/DataPortStatus.h>
#include <rtm/RTC.h>

namespace RTC {
/// What an OutPort push connection calls to hand a sample to the InPort on the other side.
class InPortConsumer
{
public:
    virtual ~InPortConsumer() = default;
    virtual void init(coil::Properties &prop) = 0;
    /// Sends one marshalled sample.
    virtual DataPortStatus put(ByteData &data) = 0;
    virtual void publishInterfaceProfile(SDOPackage::NVList &properties) = 0;
    /// Finds the InPort's interface in connector properties @p properties; false when it is not
    /// there.
    virtual bool subscribeInterface(const SDOPackage::NVList &properties) = 0;
    virtual void unsubscribeInterface(const SDOPackage::NVList &properties) = 0;
};

/// The consumers by interface type (registered by their *Init()).
using InPortConsumerFactory = ::coil::GlobalFactory<InPortConsumer>;
} // namespace RTC

#endif // RTC_INPORTCONSUMER_H
