// SPDX-License-Identifier: MIT
// Typed data InPort bound to a component's variable.
#ifndef RTM_INPORT_H
#define RTM_INPORT_H

#include <rtm/InPortBase.h>

#include <rtmruntime/dataport.h>

#include <mutex>
#include <vector>

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

    bool isNew() override
    {
        {
            std::lock_guard<std::mutex> lock(m_directMutex);
            if (m_directCount > 0)
                return true;
        }
        return InPortBase::isNew();
    }
    bool isEmpty() override { return !isNew(); }

    bool read() override
    {
        if (readDirect())
            return true;
        ::Runtime::SharedCdr bytes;
        bool littleEndian = true;
        if (!readBytes(&bytes, &littleEndian) || !::Runtime::unmarshal(bytes->view(), littleEndian, &m_value))
            return false;
        if (m_listeners.hasListeners(ConnectorDataListenerType::ON_BUFFER_READ))
            m_listeners.notifyData(ConnectorDataListenerType::ON_BUFFER_READ, std::string(), bytes->data(),
                                   static_cast<unsigned long>(bytes->size()), littleEndian);
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

    bool receiveValue(const void *value, const std::type_info &type, const std::string &connectorId) override
    {
        if (type != typeid(DataType))
            return false;
        std::lock_guard<std::mutex> lock(m_directMutex);
        // A ring of samples whose buffers are reused: after the first rounds nothing is allocated.
        if (m_directSlots.empty())
            m_directSlots.resize(directCapacity);
        const size_t index = (m_directHead + m_directCount) % m_directSlots.size();
        if (m_directCount == m_directSlots.size())
            m_directHead = (m_directHead + 1) % m_directSlots.size(); // full: the oldest is overwritten
        else
            ++m_directCount;
        DataType &slot = m_directSlots[index];
        slot = *static_cast<const DataType *>(value);
        notifySample(ConnectorDataListenerType::ON_RECEIVED, connectorId, slot);
        notifySample(ConnectorDataListenerType::ON_BUFFER_WRITE, connectorId, slot);
        return true;
    }

protected:
    DataType &m_value;

private:
    static const size_t directCapacity = 8;

    bool readDirect()
    {
        std::lock_guard<std::mutex> lock(m_directMutex);
        if (m_directCount == 0)
            return false;
        m_value = m_directSlots[m_directHead];
        m_directHead = (m_directHead + 1) % m_directSlots.size();
        --m_directCount;
        notifySample(ConnectorDataListenerType::ON_BUFFER_READ, std::string(), m_value);
        return true;
    }
    void notifySample(ConnectorDataListenerType type, const std::string &connectorId, DataType &sample)
    {
        if (m_listeners.hasListeners(type))
            m_listeners.notifyValue(type, connectorId, &sample, typeid(DataType),
                                    [&sample]() { return ::Runtime::marshal(sample, true); });
    }

    std::mutex m_directMutex;
    std::vector<DataType> m_directSlots;
    size_t m_directHead = 0;
    size_t m_directCount = 0;
};
} // namespace RTC

#endif // RTM_INPORT_H
