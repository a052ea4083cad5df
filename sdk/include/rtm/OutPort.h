// SPDX-License-Identifier: MIT
// Typed data OutPort bound to a component's variable.
#ifndef RTM_OUTPORT_H
#define RTM_OUTPORT_H

#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
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
class OutPort : public OutPortBase
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

protected:
    DataType &m_value;

private:
    bool send(DataType &value)
    {
        const DataType &sample = value;
        notifyWrite(&value, typeid(DataType), [&sample]() { return ::Runtime::marshal(sample, true); });
        writeDirect(&value, typeid(DataType));
        writeBytes([&sample](bool littleEndian) { return ::Runtime::marshalView(sample, littleEndian); });
        return true;
    }

    OnWrite<DataType> *m_onWrite = nullptr;
    OnWriteConvert<DataType> *m_onWriteConvert = nullptr;
};
} // namespace RTC

#endif // RTM_OUTPORT_H
