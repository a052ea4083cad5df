// SPDX-License-Identifier: MIT
// The receiving side's view of an OutPort: where a pull connection takes samples.
#ifndef RTC_OUTPORTCONSUMER_H
#define RTC_OUTPORTCONSUMER_H

#include <coil/Factory.h>
#include <coil/Properties.h>
#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

namespace RTC {
class ConnectorListenersBase;
class ConnectorInfo;

/// What an InPort pull connection calls to take a sample from the OutPort on the other side.
class OutPortConsumer
{
public:
    virtual ~OutPortConsumer() = default;
    virtual void init(coil::Properties &prop) = 0;
    virtual void setBuffer(CdrBufferBase *buffer) = 0;
    virtual void setListener(ConnectorInfo &info, ConnectorListenersBase *listeners) = 0;
    /// Takes one marshalled sample.
    virtual DataPortStatus get(ByteData &data) = 0;
    virtual bool subscribeInterface(const SDOPackage::NVList &properties) = 0;
    virtual void unsubscribeInterface(const SDOPackage::NVList &properties) = 0;
};

/// The consumers by interface type (registered by their *Init()).
using OutPortConsumerFactory = ::coil::GlobalFactory<OutPortConsumer>;
} // namespace RTC

#endif // RTC_OUTPORTCONSUMER_H
