// SPDX-License-Identifier: MIT
#pragma once

#include "dataport.h"
#include "inportconnector.h"

#include <memory>
#include <mutex>
#include <vector>

namespace Runtime {

/// Called for every sample that arrives at an InPort, with the id of the connector it came through.
using SampleListener = std::function<void(const CdrView &, bool littleEndian, const std::string &connectorId)>;

/// Untyped data InPort: push connections fill buffers, pull connections are asked on read.
class InPortBase : public DataPortBase
{
public:
    InPortBase(const std::string &name, const std::string &dataType, PortableServer::POA_ptr poa);
    ~InPortBase() override;

    /// True when a pushed sample waits in any connection.
    bool isNew();
    /// Takes one sample (pushed ones first, then pulls); false when none is available. The id of
    /// the connection it came through goes to @p connectorId when given.
    bool readMarshalled(SharedCdr *data, bool *littleEndian, std::string *connectorId = nullptr);
    /// Called (in the ORB's thread) for every sample that arrives, before it is buffered.
    void setReceiveListener(SampleListener listener);
    size_t connectorCount();

protected:
    RTC::ReturnCode_t publishInterfaces(RTC::ConnectorProfile &profile) override;
    RTC::ReturnCode_t subscribeInterfaces(const RTC::ConnectorProfile &profile) override;
    void unsubscribeInterfaces(const RTC::ConnectorProfile &profile) override;

private:
    std::vector<std::shared_ptr<InPortConnector>> connectors();
    void notifyReceived(const CdrView &data, bool littleEndian, const std::string &connectorId);

    PortableServer::POA_var m_poa;
    std::mutex m_mutex;
    std::vector<std::shared_ptr<InPortConnector>> m_connectors;
    SampleListener m_listener;
};

/// Typed InPort (`InPort<RTC::TimedLong>`), as OpenRTM's InPort<T>.
template <typename T>
class InPort : public InPortBase
{
public:
    InPort(const std::string &name, PortableServer::POA_ptr poa)
        : InPortBase(name, repositoryId<T>(), poa)
    {
    }
    /// Reads one sample into @p value; false when none was available or it did not unmarshal.
    bool read(T *value)
    {
        SharedCdr data;
        bool littleEndian = true;
        return readMarshalled(&data, &littleEndian) && unmarshal(data->view(), littleEndian, value);
    }
};

} // namespace Runtime
