// SPDX-License-Identifier: MIT
// Typed data InPort bound to a component's variable.
#ifndef RTM_INPORT_H
#define RTM_INPORT_H

#include <rtm/InPortBase.h>

#include <rtmruntime/dataport.h>

namespace RTC
{
/**
 * An InPort of samples of @p DataType (an IDL struct such as RTC::TimedLong) bound to the
 * component's variable: read() takes the next waiting sample into it.
 */
template <class DataType>
class InPort : public InPortBase
{
public:
    /// The extra arguments of OpenRTM-aist 1.x (buffer length, blocking, timeouts) are accepted and ignored.
    InPort(const char *name, DataType &value, int bufsize = 64, bool read_block = false, bool write_block = false,
           int read_timeout = 0, int write_timeout = 0)
        : InPortBase(name, ::Runtime::repositoryId<DataType>().c_str()), m_value(value)
    {
        (void)bufsize;
        (void)read_block;
        (void)write_block;
        (void)read_timeout;
        (void)write_timeout;
    }
    ~InPort() override = default;

    /// The port's name.
    const char *name() const { return ::Runtime::PortBase::name().c_str(); }

    bool read() override
    {
        ::Runtime::CdrBytes bytes;
        bool littleEndian = true;
        if (!readBytes(&bytes, &littleEndian) || !::Runtime::unmarshal(bytes, littleEndian, &m_value))
            return false;
        if (m_listeners.hasListeners(ConnectorDataListenerType::ON_BUFFER_READ))
            m_listeners.notifyData(ConnectorDataListenerType::ON_BUFFER_READ, std::string(), bytes.data(),
                                   static_cast<unsigned long>(bytes.size()), littleEndian);
        return true;
    }
    /// Reads into the bound variable (OpenRTM's update()).
    virtual void update() { read(); }
    /// Reads and copies the bound variable into @p rhs.
    void operator>>(DataType &rhs)
    {
        read();
        rhs = m_value;
    }

protected:
    DataType &m_value;
};
} // namespace RTC

#endif // RTM_INPORT_H
