// SPDX-License-Identifier: MIT
// PortAdmin: ports by name, servants of this process and references to others'.
#include <rtm/PortAdmin.h>

#include <algorithm>

namespace RTC {

PortAdmin::PortAdmin(CORBA::ORB_ptr orb, PortableServer::POA_ptr poa)
    : m_pORB(CORBA::ORB::_duplicate(orb))
    , m_pPOA(PortableServer::POA::_duplicate(poa))
    , rtclog("PortAdmin")
{ }

PortAdmin::~PortAdmin() = default;

std::string PortAdmin::nameOf(PortService_ptr port)
{
    try {
        PortProfile_var profile = port->get_port_profile();
        return std::string(profile->name);
    } catch (const CORBA::Exception &) {
        return std::string();
    }
}

PortServiceList *PortAdmin::getPortServiceList() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    auto *list = new PortServiceList;
    list->length(CORBA::ULong(m_ports.size()));
    for (CORBA::ULong i = 0; i < list->length(); ++i)
        (*list)[i] = PortService::_duplicate(m_ports[i].ref);
    return list;
}

PortProfileList PortAdmin::getPortProfileList() const
{
    std::vector<PortService_var> refs;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        for (const Entry &entry : m_ports)
            refs.push_back(entry.ref);
    }
    PortProfileList profiles;
    for (PortService_var &ref : refs) {
        try {
            PortProfile_var profile = ref->get_port_profile();
            const CORBA::ULong n = profiles.length();
            profiles.length(n + 1);
            profiles[n] = profile.in();
        } catch (const CORBA::Exception &) {
            // A port of another process that went away has no profile to give.
        }
    }
    return profiles;
}

PortService_ptr PortAdmin::getPortRef(const char *port_name) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const Entry &entry : m_ports) {
        if (port_name != nullptr && entry.name == port_name)
            return entry.ref.in();
    }
    return PortService::_nil();
}

PortBase *PortAdmin::getPort(const char *port_name) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const Entry &entry : m_ports) {
        if (port_name != nullptr && entry.name == port_name)
            return entry.servant;
    }
    return nullptr;
}

bool PortAdmin::addPort(PortBase &port)
{
    PortService_var ref = port.reference();
    const std::string name(port.getName());
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const Entry &entry : m_ports) {
        if (entry.name == name)
            return false;
    }
    m_ports.push_back(Entry {name, &port, ref});
    return true;
}

bool PortAdmin::addPort(PortService_ptr port)
{
    if (CORBA::is_nil(port))
        return false;
    const std::string name = nameOf(port);
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const Entry &entry : m_ports) {
        if (entry.name == name)
            return false;
    }
    m_ports.push_back(Entry {name, nullptr, PortService::_duplicate(port)});
    return true;
}

void PortAdmin::registerPort(PortBase &port)
{
    if (!addPort(port))
        RTC_ERROR(("registerPort: a port named %s is listed already", port.getName()));
}

void PortAdmin::registerPort(PortService_ptr port)
{
    if (!addPort(port))
        RTC_ERROR(("registerPort: the port is nil or its name is listed already"));
}

bool PortAdmin::removePort(PortBase &port)
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        auto it = std::find_if(m_ports.begin(), m_ports.end(),
                               [&port](const Entry &e) { return e.servant == &port; });
        if (it == m_ports.end())
            return false;
        m_ports.erase(it);
    }
    port.disconnect_all();
    return true;
}

bool PortAdmin::removePort(PortService_ptr port)
{
    PortService_var removed;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        auto it = std::find_if(m_ports.begin(), m_ports.end(),
                               [port](const Entry &e) { return e.ref->_is_equivalent(port); });
        if (it == m_ports.end())
            return false;
        removed = it->ref;
        m_ports.erase(it);
    }
    try {
        removed->disconnect_all();
    } catch (const CORBA::Exception &) {
        // Another process's port that went away holds no connections of ours any more.
    }
    return true;
}

void PortAdmin::deletePort(PortBase &port)
{
    removePort(port);
}

void PortAdmin::deletePort(PortService_ptr port)
{
    removePort(port);
}

void PortAdmin::deletePortByName(const char *port_name)
{
    PortBase *servant = getPort(port_name);
    if (servant != nullptr) {
        removePort(*servant);
        return;
    }
    PortService_var ref = PortService::_duplicate(getPortRef(port_name));
    if (!CORBA::is_nil(ref))
        removePort(ref.in());
}

void PortAdmin::activatePorts()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    for (Entry &entry : m_ports) {
        if (entry.servant != nullptr)
            entry.servant->activateInterfaces();
    }
}

void PortAdmin::deactivatePorts()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    for (Entry &entry : m_ports) {
        if (entry.servant != nullptr)
            entry.servant->deactivateInterfaces();
    }
}

void PortAdmin::finalizePorts()
{
    deactivatePorts();
    std::vector<Entry> ports;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        ports.swap(m_ports);
    }
    for (Entry &entry : ports) {
        try {
            entry.ref->disconnect_all();
        } catch (const CORBA::Exception &) { }
    }
}

} // namespace RTC
