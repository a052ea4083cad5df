// SPDX-License-Identifier: MIT
// The untyped part of a data InPort.
#ifndef RTM_INPORTBASE_H
#define RTM_INPORTBASE_H

#include <rtm/ConnectorListener.h>
#include <rtm/DataPortListeners.h>
#include <rtm/ByteData.h>
#include <rtm/DataPortStatus.h>
#include <rtm/InPortConnector.h>
#include <rtm/PortBase.h>

#include <rtmruntime/inport.h>

#include <mutex>
#include <string>
#include <typeinfo>
#include <vector>

namespace RTC
{
/**
 * A data InPort without its sample type: connections (push and pull over CORBA CDR), the
 * port's properties and its listeners. InPort<T> adds the typed variable.
 */
class InPortBase : public ::Runtime::InPortBase, public DataPortListeners
{
public:
    using ConnectorList = std::vector<InPortConnector *>;

    /// @p data_type is the repository id of the sample type (`IDL:RTC/TimedLong:1.0`).
    InPortBase(const char *name, const char *data_type);
    ~InPortBase() override;

    /**
     * Takes the next sample into the bound variable; false when none was waiting. A non-empty
     * @p name must be the name of one of the port's connections (see InPort::read).
     */
    virtual bool read(std::string name = "") = 0;
    /// True when a sample waits in a push connection.
    virtual bool isNew();
    /// True when no sample waits.
    virtual bool isEmpty();
    /**
     * RT Studio: takes a sample that an OutPort of the same process hands over without
     * marshalling (a push/flush connection between two SDK ports of one type). False when the
     * port does not hold samples of @p type.
     */
    virtual bool receiveValue(const void *value, const std::type_info &type, const std::string &connectorId);
    /**
     * RT Studio: whether the port takes samples as values from OutPorts of the same process
     * (receiveValue()). False for ports whose samples exist only as CDR (Python components'):
     * their connections inside one process carry bytes.
     */
    virtual bool takesValues() const { return true; }

    /**
     * One connector object per connection (valid until the connection goes): its profile, its
     * id and name, disconnect() and read() of the next sample (on a port with one connection).
     */
    const std::vector<InPortConnector *> &connectors();
    /// The connection @p id; null when the port has none of that id.
    InPortConnector *getConnectorById(const char *id);
    /// The connection named @p name; null when the port has none of that name.
    InPortConnector *getConnectorByName(const char *name);

    /// RT Studio: takes the next waiting sample as bytes and their byte order; false when none waits.
    virtual bool takeMarshalled(ByteData &data, bool &littleEndian);
    /**
     * RT Studio: a marshalled sample an OutPort connector object of this process writes to a
     * connection of this port; false when it is not a sample of the port's type.
     */
    virtual bool receiveMarshalled(const ByteData &data, bool littleEndian, const std::string &connectorId);

    ReturnCode_t notify_connect(ConnectorProfile &connector_profile) override;
    ReturnCode_t notify_disconnect(const char *connector_id) override;

protected:
    /// Writes the runtime's refusal of a connector to the component's log.
    void refused(const ConnectorProfile &profile, const std::string &problem) const override;
    /// The settings init() took, under each connector's own.
    ::Runtime::Properties connectorDefaults() const override { return connectorSettings(); }
    /// Logs that @p operation on connection @p name cannot be done on a port with several connections.
    void logUnsupported(const char *operation, const std::string &name);
    /// Takes one marshalled sample; false when none was waiting. The id of the connection it came
    /// through goes to @p connectorId when given.
    bool readBytes(::Runtime::SharedCdr *data, bool *littleEndian, std::string *connectorId = nullptr);

private:
    std::mutex m_connectorsMutex;
    std::vector<InPortConnector *> m_connectors;
};
} // namespace RTC

#endif // RTM_INPORTBASE_H
