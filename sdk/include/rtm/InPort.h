// SPDX-License-Identifier: MIT
// Typed data InPort bound to a component's variable.
#ifndef RTM_INPORT_H
#define RTM_INPORT_H

#include <rtm/CdrBufferBase.h>
#include <rtm/DataPortStatus.h>
#include <rtm/DirectInPortBase.h>
#include <rtm/InPortBase.h>
#include <rtm/InPortConnector.h>
#include <rtm/PortCallback.h>
#include <rtm/RTC.h>
#include <rtm/Timestamp.h>

#include <rtmruntime/dataport.h>

#include <coil/stringutil.h>

#include <mutex>
#include <string>
#include <sys/utsname.h>
#include <vector>

namespace RTC
{
/**
 * An InPort of samples of @p DataType (an IDL struct such as RTC::TimedLong) bound to the
 * component's variable: read() takes the next waiting sample into it. Callbacks set with
 * setOnRead / setOnReadConvert (and OpenRTM-aist 0.4's setOnUnderflow / setOnOverflow) are
 * called at the moments OpenRTM-aist calls them; the port does not own them.
 */
template <class DataType>
class InPort : public InPortBase, public DirectInPortBase<DataType>
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

    /// The port's name as given to the constructor.
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
    /// Whether a sample waits in connection @p name (false when the port has no such connection).
    virtual bool isNew(std::string name) { return singleConnection(name, "isNew") && isNew(); }
    /// Whether a sample waits in one of the connections @p names; those that have one are left in @p names.
    virtual bool isNew(coil::vstring &names)
    {
        coil::vstring fresh;
        for (const std::string &name : names) {
            if (isNew(name))
                fresh.push_back(name);
        }
        names = fresh;
        return !fresh.empty();
    }
    bool isEmpty() override { return !isNew(); }
    /// Whether connection @p name has nothing waiting (false when the port has no such connection).
    virtual bool isEmpty(std::string name) { return singleConnection(name, "isEmpty") && isEmpty(); }
    /// Whether one of the connections @p names has nothing waiting; those are left in @p names.
    virtual bool isEmpty(coil::vstring &names)
    {
        coil::vstring empty;
        for (const std::string &name : names) {
            if (isEmpty(name))
                empty.push_back(name);
        }
        names = empty;
        return !empty.empty();
    }

    /**
     * Takes the next sample into the bound variable. The OnRead callback is called first; the
     * OnReadConvert callback then replaces what was read. When nothing waits, an OnUnderflow
     * callback supplies the value (and read() is true), else read() is false. A non-empty
     * @p name must name a connection; with several connections the samples cannot be told apart
     * by connection and such a read fails (logged).
     */
    bool read(std::string name = "") override
    {
        if (m_onRead != nullptr)
            (*m_onRead)();
        if (!name.empty() && !singleConnection(name, "read")) {
            m_status = DataPortStatus::PRECONDITION_NOT_MET;
            return false;
        }
        if (!takeSample()) {
            m_status = DataPortStatus::BUFFER_EMPTY;
            if (m_onUnderflow == nullptr)
                return false;
            m_value = (*m_onUnderflow)();
            return true;
        }
        m_status = DataPortStatus::PORT_OK;
        if (m_onReadConvert != nullptr)
            m_value = (*m_onReadConvert)(m_value);
        return true;
    }
    /// The result of the last read (there is one status: @p index is not used).
    DataPortStatus getStatus(int index)
    {
        (void)index;
        return m_status;
    }
    /// The result of the last read, as a list of one.
    DataPortStatusList getStatusList() { return DataPortStatusList(1, m_status); }

    /// Calls @p on_read (not owned; null: none) at the start of each read().
    inline void setOnRead(OnRead<DataType> *on_read) { m_onRead = on_read; }
    /// Gives the bound variable what @p on_rconvert returns for each sample read (not owned).
    inline void setOnReadConvert(OnReadConvert<DataType> *on_rconvert) { m_onReadConvert = on_rconvert; }
    /// OpenRTM-aist 0.4: a read that finds no sample gives the bound variable what @p on_underflow returns.
    inline void setOnUnderflow(OnUnderflow<DataType> *on_underflow) { m_onUnderflow = on_underflow; }
    /**
     * OpenRTM-aist 0.4: called with a sample that arrives from a connection inside this process
     * while the port holds as many as it can (the oldest waiting sample is dropped for it).
     */
    inline void setOnOverflow(OnOverflow<DataType> *on_overflow) { m_onOverflow = on_overflow; }

    bool takeMarshalled(ByteData &data, bool &littleEndian) override
    {
        DataType sample;
        if (takeDirect(&sample)) {
            const std::vector<unsigned char> bytes = ::Runtime::marshal(sample, true);
            data.writeData(bytes.data(), static_cast<unsigned long>(bytes.size()));
            littleEndian = true;
            return true;
        }
        return InPortBase::takeMarshalled(data, littleEndian);
    }
    bool receiveMarshalled(const ByteData &data, bool littleEndian, const std::string &connectorId) override
    {
        DataType sample;
        const ::Runtime::CdrView view(data.getBuffer(), data.getDataLength());
        return ::Runtime::unmarshal(view, littleEndian, &sample) && receiveValue(&sample, typeid(DataType), connectorId);
    }

    /// Puts @p data into the port as if a connection delivered it (OpenRTM-aist's direct write).
    void write(DataType &data) override { receiveValue(&data, typeid(DataType), std::string()); }

    /// Reads into the bound variable (OpenRTM-aist's update()).
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
        if (m_directCount == m_directSlots.size()) {
            m_directHead = (m_directHead + 1) % m_directSlots.size(); // full: the oldest is overwritten
            if (m_onOverflow != nullptr)
                (*m_onOverflow)(*static_cast<const DataType *>(value));
        } else
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

    // A sample from a connection inside this process, else one from the runtime's connections.
    bool takeSample()
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

    // Whether connection @p name exists and is the port's only one (a read by name is then a plain read).
    bool singleConnection(const std::string &name, const char *operation)
    {
        const coil::vstring names = getConnectorNames();
        bool known = false;
        for (const std::string &n : names)
            known = known || n == name;
        if (!known)
            return false;
        if (names.size() == 1)
            return true;
        logUnsupported(operation, name);
        return false;
    }

    bool readDirect() { return takeDirect(&m_value); }
    // The oldest sample a connection of this process handed over, into @p sample.
    bool takeDirect(DataType *sample)
    {
        std::lock_guard<std::mutex> lock(m_directMutex);
        if (m_directCount == 0)
            return false;
        *sample = m_directSlots[m_directHead];
        m_directHead = (m_directHead + 1) % m_directSlots.size();
        --m_directCount;
        notifySample(ConnectorDataListenerType::ON_BUFFER_READ, std::string(), *sample);
        return true;
    }
    void notifySample(ConnectorDataListenerType type, const std::string &connectorId, DataType &sample)
    {
        if (m_listeners.hasListeners(type))
            m_listeners.notifyValue(type, connectorId, &sample, typeid(DataType),
                                    [&sample]() { return ::Runtime::marshal(sample, true); });
    }

    OnRead<DataType> *m_onRead = nullptr;
    OnReadConvert<DataType> *m_onReadConvert = nullptr;
    OnUnderflow<DataType> *m_onUnderflow = nullptr;
    OnOverflow<DataType> *m_onOverflow = nullptr;
    DataPortStatus m_status = DataPortStatus::PORT_OK;
    std::mutex m_directMutex;
    std::vector<DataType> m_directSlots;
    size_t m_directHead = 0;
    size_t m_directCount = 0;
};
} // namespace RTC

#endif // RTM_INPORT_H
