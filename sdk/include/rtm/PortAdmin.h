// SPDX-License-Identifier: MIT
// A list of ports by name, as a component keeps its ports.
#ifndef RTC_PORTADMIN_H
#define RTC_PORTADMIN_H

#include <rtm/PortBase.h>
#include <rtm/RTC.h>
#include <rtm/SystemLogger.h>

#include <array>
#include <compare>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

namespace RTC {
/**
 * Ports by name: servants of this process (PortBase) and references to others' ports. Names
 * are the ports' profile names and must be unique. Thread-safe; the ports stay their owners'.
 */
class PortAdmin
{
public:
    PortAdmin(CORBA::ORB_ptr orb, PortableServer::POA_ptr poa);
    virtual ~PortAdmin();

    /// References to every port (the caller owns the list).
    PortServiceList *getPortServiceList() const;
    /// The profiles of every port.
    PortProfileList getPortProfileList() const;
    /// The reference of port @p port_name (not duplicated); nil when there is none.
    PortService_ptr getPortRef(const char *port_name) const;
    /// The servant of port @p port_name; null when there is none or it is another process's.
    PortBase *getPort(const char *port_name) const;
    /// Adds @p port; false when a port of its name is listed already.
    bool addPort(PortBase &port);
    bool addPort(PortService_ptr port);
    void registerPort(PortBase &port);
    void registerPort(PortService_ptr port);
    /// Disconnects @p port and takes it off the list; false when it is not listed.
    bool removePort(PortBase &port);
    bool removePort(PortService_ptr port);
    void deletePort(PortBase &port);
    void deletePort(PortService_ptr port);
    void deletePortByName(const char *port_name);
    /// Lets the listed servants offer their interfaces (activateInterfaces()).
    void activatePorts();
    void deactivatePorts();
    /// Deactivates and removes every port.
    void finalizePorts();

private:
    struct Entry
    {
        std::string name;
        PortBase *servant;
        PortService_var ref;
    };
    static std::string nameOf(PortService_ptr port);

    CORBA::ORB_var m_pORB;
    PortableServer::POA_var m_pPOA;
    mutable std::mutex m_mutex;
    std::vector<Entry> m_ports;
    mutable Logger rtclog;
};
} // namespace RTC

#endif // RTC_PORTADMIN_H
