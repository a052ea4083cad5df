// SPDX-License-Identifier: MIT
// Typed data OutPort bound to a component's variable.
#ifndef RTM_OUTPORT_H
#define RTM_OUTPORT_H

#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/DirectOutPortBase.h>
#include <rtm/OutPortBase.h>
#include <rtm/OutPortConnector.h>
#include <rtm/PortCallback.h>
#include <rtm/RTC.h>
#include <rtm/Timestamp.h>

#include <functional>
#include <rtmruntime/dataport.h>
#include <string>
#include <sys/utsname.h>
#include <vector>

namespace RTC
{
/**
 * An OutPort of samples of @p DataType bound to the component's variable. Callbacks set with
 * setOnWrite / setOnWriteConvert are called as OpenRTM-aist calls them; the port does not own them.
 */
template <class DataType>
class OutPort : public OutPortBase, public DirectOutPortBase<DataType>
{
public:
    OutPort(const char *name, DataType &value)
        : OutPortBase(name, ::Runtime::repositoryId<DataType>().c_str()), m_value(value)
    {
    }
    ~OutPort() override = default;

    /// The port's name as given to the constructor.
    const char *name() const { return ::Runtime::PortBase::name().c_str(); }

    /**
     * Sends @p value to every connection (push: at once or by the connection's policy). The
     * OnWrite callback sees @p value first; when an OnWriteConvert callback is set, what it
     * returns is sent instead.
     */
    virtual bool write(DataType &value)
    {
        if (m_onWrite != nullptr)
            (*m_onWrite)(value);
        if (m_onWriteConvert == nullptr)
            return send(value);
        DataType converted = (*m_onWriteConvert)(value);
        return send(converted);
    }
    bool write() override { return write(m_value); }
    bool operator<<(DataType &value) { return write(value); }

    /// Calls @p on_write (not owned; null: none) with each value about to be written.
    inline void setOnWrite(OnWrite<DataType> *on_write) { m_onWrite = on_write; }
    /// Sends what @p on_wconvert returns for each value written (not owned; null: none).
    inline void setOnWriteConvert(OnWriteConvert<DataType> *on_wconvert) { m_onWriteConvert = on_wconvert; }

    /**
     * What the last write() did on connection @p index (in the order of connectors()):
     * PORT_OK, BUFFER_FULL / BUFFER_TIMEOUT (the buffer or the peer's), CONNECTION_LOST, …
     * PORT_ERROR for an index out of range.
     */
    DataPortStatus getStatus(int index)
    {
        const DataPortStatusList list = statusList();
        return index >= 0 && size_t(index) < list.size() ? list[size_t(index)] : DataPortStatus::PORT_ERROR;
    }
    DataPortStatusList getStatusList() { return statusList(); }
    /// The port as the in-process sender of its samples (InPortConnector::getDirectData).
    DirectPortBase *getDirectPort() override { return static_cast<DirectOutPortBase<DataType> *>(this); }

    // The latest value written, for a reader in the same process (OpenRTM-aist's pull-direct side).
    /// Copies the latest value written into @p data; isNew() is false afterwards.
    void read(DataType &data) override
    {
        std::lock_guard<std::mutex> guard(m_latestMutex);
        m_latestNew = false;
        data = m_latest;
    }
    /// True when no value was written since the last read().
    bool isEmpty() override { return !isNew(); }
    /// True when a value was written since the last read().
    bool isNew() override
    {
        std::lock_guard<std::mutex> guard(m_latestMutex);
        return m_latestNew;
    }

protected:
    DataType &m_value;

private:
    bool send(DataType &value)
    {
        const DataType &sample = value;
        notifyWrite(&value, typeid(DataType), [&sample]() { return ::Runtime::marshal(sample, true); });
        writeDirect(&value, typeid(DataType));
        writeBytes([&sample](bool littleEndian) { return ::Runtime::marshalView(sample, littleEndian); });
        {
            std::lock_guard<std::mutex> guard(m_latestMutex);
            m_latest = value;
            m_latestNew = true;
        }
        return true;
    }

    std::mutex m_latestMutex;
    DataType m_latest;
    bool m_latestNew = false;

    OnWrite<DataType> *m_onWrite = nullptr;
    OnWriteConvert<DataType> *m_onWriteConvert = nullptr;
};
} // namespace RTC

#endif // RTM_OUTPORT_H
