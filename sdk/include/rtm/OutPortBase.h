// SPDX-License-Identifier: MIT
// The untyped part of a data OutPort.
#ifndef RTM_OUTPORTBASE_H
#define RTM_OUTPORTBASE_H

#include <rtm/ConnectorListener.h>
#include <rtm/DataPortStatus.h>
#include <rtm/DataPortListeners.h>
#include <rtm/InPortBase.h>
#include <rtm/OutPortConnector.h>
#include <rtm/PortBase.h>

#include <rtmruntime/outport.h>

#include <mutex>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace RTC
{
/// A data OutPort without its sample type: connections, properties and listeners.
class OutPortBase : public ::Runtime::OutPortBase, public DataPortListeners
{
public:
    using ConnectorList = std::vector<OutPortConnector *>;

    /// @p data_type is the repository id of the sample type (`IDL:RTC/TimedLong:1.0`).
    OutPortBase(const char *name, const char *data_type);
    ~OutPortBase() override;

    /// Sends the bound variable to every connection.
    virtual bool write() = 0;

    /**
     * One connector object per connection (valid until the connection goes): its profile, its
     * id and name, disconnect() and write() of a marshalled sample (on a port with one connection).
     */
    const std::vector<OutPortConnector *> &connectors();
    /// The connection @p id; null when the port has none of that id.
    OutPortConnector *getConnectorById(const char *id);
    /// The connection named @p name; null when the port has none of that name.
    OutPortConnector *getConnectorByName(const char *name);
    /// RT Studio: sends a marshalled sample through connection @p connectorId (the port's only one).
    bool writeMarshalledTo(const std::string &connectorId, const ByteData &data, bool littleEndian);

    ReturnCode_t notify_connect(ConnectorProfile &connector_profile) override;
    ReturnCode_t notify_disconnect(const char *connector_id) override;

    /**
     * RT Studio: whether the port hands samples as values to InPorts of the same process. False
     * for ports whose samples exist only as CDR (Python components'): their connections carry bytes.
     */
    virtual bool givesValues() const { return true; }
    /// RT Studio: hands samples of connection @p connectorId to @p inport directly (same process).
    void addDirectPeer(const std::string &connectorId, InPortBase *inport);
    void removeDirectPeer(const std::string &connectorId);

protected:
    /// Writes the runtime's refusal of a connector to the component's log.
    void refused(const ConnectorProfile &profile, const std::string &problem) const override;
    /// The settings init() took, under each connector's own.
    ::Runtime::Properties connectorDefaults() const override { return connectorSettings(); }
    /// Gives @p value to the InPorts of this process connected directly (one copy, no marshalling).
    void writeDirect(const void *value, const std::type_info &type);
    /// Calls the ON_BUFFER_WRITE and ON_SEND listeners with a sample about to be sent.
    void notifyWrite(void *value, const std::type_info &type, const std::function<std::vector<unsigned char>()> &marshal);

    /// Hands a sample to the connections; @p marshal gives its bytes in the byte order asked for.
    /// What each connection did with it is kept for statusList().
    void writeBytes(const std::function<::Runtime::CdrView(bool littleEndian)> &marshal);
    /// The same for a port with user serializers (setUserSerializers()): @p marshal gives the
    /// bytes of one marshaling type (`cdr` or a serializer's name); no data fails those connections.
    void writeBytesAs(const std::function<::Runtime::CdrView(bool littleEndian, const std::string &marshalingType)> &marshal);
    /// What the last write did on each connection, in the order of connectors().
    DataPortStatusList statusList();

private:
    /// Keeps what each connection did with the last sample, for statusList().
    void keepStatuses(const SendResults &results);

    std::mutex m_statusMutex;
    DataPortStatusList m_status;
    std::mutex m_directMutex;
    std::vector<std::pair<std::string, InPortBase *>> m_directPeers;
    std::mutex m_connectorsMutex;
    std::vector<OutPortConnector *> m_connectors;
};
} // namespace RTC

#endif // RTM_OUTPORTBASE_H
