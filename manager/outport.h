// SPDX-License-Identifier: MIT
#pragma once

#include "dataport.h"
#include "outportconnector.h"

#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <vector>

namespace Runtime {

/// Untyped data OutPort: hands marshalled samples to every connection.
class OutPortBase : public DataPortBase
{
public:
    OutPortBase(const std::string &name, const std::string &dataType, PortableServer::POA_ptr poa);
    ~OutPortBase() override;

    /// What each connection (by id) did with a sample; bypassed connections are not listed.
    using SendResults = std::vector<std::pair<std::string, SendStatus>>;
    /**
     * Sends one sample; @p marshalIn produces its plain CDR in the requested byte order (called at
     * most twice; each view only has to last until the next call).
     */
    SendResults writeMarshalled(const std::function<CdrView(bool littleEndian)> &marshalIn);
    /**
     * Sends one sample to connections of any marshaling type (setUserSerializers()): @p marshalIn
     * produces its bytes for one marshaling type (`cdr` or a user serializer's name) in one byte
     * order, once per pair in use; a view with no data fails that pair's connections (PortError).
     */
    SendResults writeMarshalledAs(
        const std::function<CdrView(bool littleEndian, const std::string &marshalingType)> &marshalIn);
    /**
     * Leaves connection @p connectorId out of writeMarshalled() (@p bypassed true) or takes it back:
     * the SDK hands such samples to an InPort of the same process itself, without marshalling.
     */
    void setBypassed(const std::string &connectorId, bool bypassed);
    size_t connectorCount();

protected:
    RTC::ReturnCode_t publishInterfaces(RTC::ConnectorProfile &profile) override;
    RTC::ReturnCode_t subscribeInterfaces(const RTC::ConnectorProfile &profile) override;
    void unsubscribeInterfaces(const RTC::ConnectorProfile &profile) override;

private:
    PortableServer::POA_var m_poa;
    std::mutex m_mutex;
    std::vector<std::shared_ptr<OutPortConnector>> m_connectors;
    std::set<std::string> m_bypassed;
};

/// Typed OutPort (`OutPort<RTC::TimedLong>`), as OpenRTM's OutPort<T>.
template <typename T>
class OutPort : public OutPortBase
{
public:
    OutPort(const std::string &name, PortableServer::POA_ptr poa)
        : OutPortBase(name, repositoryId<T>(), poa)
    {
    }
    void write(const T &value)
    {
        writeMarshalled([&value](bool littleEndian) { return marshalView(value, littleEndian); });
    }
};

} // namespace Runtime
