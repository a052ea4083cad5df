// SPDX-License-Identifier: MIT
// Typed data OutPort bound to a component's variable.
#ifndef RTM_OUTPORT_H
#define RTM_OUTPORT_H

#include <rtm/OutPortBase.h>
#include <rtm/Timestamp.h>

#include <rtmruntime/dataport.h>

namespace RTC
{
/// An OutPort of samples of @p DataType bound to the component's variable.
template <class DataType>
class OutPort : public OutPortBase
{
public:
    OutPort(const char *name, DataType &value)
        : OutPortBase(name, ::Runtime::repositoryId<DataType>().c_str()), m_value(value)
    {
    }
    ~OutPort() override = default;

    const char *name() const { return ::Runtime::PortBase::name().c_str(); }

    /// Sends @p value to every connection (push: at once or by the connection's policy).
    virtual bool write(DataType &value)
    {
        const DataType &sample = value;
        notifyWrite(&value, typeid(DataType), [&sample]() { return ::Runtime::marshal(sample, true); });
        writeDirect(&value, typeid(DataType));
        writeBytes([&sample](bool littleEndian) { return ::Runtime::marshalView(sample, littleEndian); });
        return true;
    }
    bool write() override { return write(m_value); }
    bool operator<<(DataType &value) { return write(value); }

protected:
    DataType &m_value;
};
} // namespace RTC

#endif // RTM_OUTPORT_H
