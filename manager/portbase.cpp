// SPDX-License-Identifier: MIT
#include "portbase.h"

#include <iostream>

#include "corbautil.h"

#include <cctype>
#include <memory>

namespace Runtime {

namespace {

// "IDL:RTC/TimedLong:1.0" → "RTC::TimedLong"; "RTC::TimedLong" and "TimedLong" stay as they are.
std::string canonicalType(const std::string &name)
{
    std::string type = name;
    if (type.compare(0, 4, "IDL:") == 0) {
        type = type.substr(4);
        const size_t colon = type.rfind(':');
        if (colon != std::string::npos)
            type = type.substr(0, colon);
        std::string scoped;
        for (char c : type)
            scoped += c == '/' ? std::string("::") : std::string(1, c);
        type = scoped;
    }
    return type;
}

bool isAnyType(const std::string &type)
{
    return type.size() == 3 && std::tolower(static_cast<unsigned char>(type[0])) == 'a'
           && std::tolower(static_cast<unsigned char>(type[1])) == 'n'
           && std::tolower(static_cast<unsigned char>(type[2])) == 'y';
}

std::string lastSegment(const std::string &scoped)
{
    const size_t pos = scoped.rfind("::");
    return pos == std::string::npos ? scoped : scoped.substr(pos + 2);
}

} // namespace

bool sameDataType(const std::string &a, const std::string &b)
{
    if (isAnyType(a) || isAnyType(b))
        return true;
    const std::string ca = canonicalType(a);
    const std::string cb = canonicalType(b);
    if (ca == cb)
        return true;
    // A bare name (OpenRTM 1.x style "TimedLong") matches any module's type of that name.
    const bool aBare = ca.find("::") == std::string::npos;
    const bool bBare = cb.find("::") == std::string::npos;
    return (aBare || bBare) && lastSegment(ca) == lastSegment(cb);
}

PortBase::PortBase(const std::string &name)
    : m_name(name)
{
    m_profile.name = name.c_str();
}

PortBase::~PortBase() = default;

void PortBase::setOwner(RTC::RTObject_ptr owner, const std::string &instanceName)
{
    std::lock_guard lock(m_mutex);
    m_profile.owner = RTC::RTObject::_duplicate(owner);
    m_profile.name = (instanceName + '.' + m_name).c_str();
}

void PortBase::setName(const char *name)
{
    std::lock_guard lock(m_mutex);
    m_profile.name = name != nullptr ? name : "";
}

void PortBase::setPortRef(RTC::PortService_ptr port_ref)
{
    RTC::PortService_var own = reference();
    if (CORBA::is_nil(port_ref) || !own->_is_equivalent(port_ref))
        std::cerr << programName() << ": port " << getName()
                  << ": setPortRef: a port's reference is its own servant's; another reference is refused"
                  << std::endl;
}

void PortBase::setProperty(const std::string &key, const std::string &value)
{
    std::lock_guard lock(m_mutex);
    nvSet(m_profile.properties, key, value);
}

RTC::PortService_ptr PortBase::reference()
{
    std::lock_guard lock(m_mutex);
    if (CORBA::is_nil(m_self)) {
        m_self = _this();
        m_profile.port_ref = RTC::PortService::_duplicate(m_self);
    }
    return RTC::PortService::_duplicate(m_self);
}

size_t PortBase::connectionCount()
{
    std::lock_guard lock(m_mutex);
    return m_profile.connector_profiles.length();
}

void PortBase::setConnectObserver(ConnectObserver observer)
{
    std::lock_guard lock(m_mutex);
    m_observer = std::move(observer);
}

const char *PortBase::getName() const
{
    std::lock_guard lock(m_mutex);
    return m_profile.name;
}

const RTC::PortProfile &PortBase::getPortProfile() const
{
    return m_profile;
}

RTC::PortService_ptr PortBase::getPortRef() const
{
    std::lock_guard lock(m_mutex);
    return m_self.in();
}

void PortBase::observe(ConnectStep step, RTC::ConnectorProfile &profile, RTC::ReturnCode_t result)
{
    ConnectObserver observer;
    {
        std::lock_guard lock(m_mutex);
        observer = m_observer;
    }
    if (observer)
        observer(step, profile, result);
}

void PortBase::callHook(Hook hook, RTC::ConnectorProfile &profile)
{
    HookFunction function;
    {
        std::lock_guard lock(m_mutex);
        function = m_hooks[hook];
    }
    if (function)
        function(profile);
}

Properties PortBase::portProperties()
{
    std::lock_guard lock(m_mutex);
    return nvToProperties(m_profile.properties);
}

std::string PortBase::profileName()
{
    std::lock_guard lock(m_mutex);
    return std::string(m_profile.name);
}

void PortBase::addInterfaceProfile(const std::string &instanceName, const std::string &typeName, bool provided)
{
    std::lock_guard lock(m_mutex);
    const CORBA::ULong n = m_profile.interfaces.length();
    m_profile.interfaces.length(n + 1);
    m_profile.interfaces[n].instance_name = instanceName.c_str();
    m_profile.interfaces[n].type_name = typeName.c_str();
    m_profile.interfaces[n].polarity = provided ? RTC::PROVIDED : RTC::REQUIRED;
}

RTC::PortProfile *PortBase::get_port_profile()
{
    RTC::PortService_var self = reference();
    std::lock_guard lock(m_mutex);
    return new RTC::PortProfile(m_profile);
}

RTC::ConnectorProfileList *PortBase::get_connector_profiles()
{
    std::lock_guard lock(m_mutex);
    return new RTC::ConnectorProfileList(m_profile.connector_profiles);
}

RTC::ConnectorProfile *PortBase::get_connector_profile(const char *connector_id)
{
    RTC::ConnectorProfile profile;
    if (!findProfile(connector_id ? connector_id : "", &profile))
        return new RTC::ConnectorProfile;
    return new RTC::ConnectorProfile(profile);
}

RTC::ReturnCode_t PortBase::connect(RTC::ConnectorProfile &connector_profile)
{
    if (connector_profile.ports.length() == 0)
        return RTC::BAD_PARAMETER;
    std::string id(connector_profile.connector_id);
    if (id.empty()) {
        id = newUuid();
        connector_profile.connector_id = id.c_str();
    } else {
        // OpenRTM-aist answers a connector id it already holds with PRECONDITION_NOT_MET.
        RTC::ConnectorProfile existing;
        if (findProfile(id, &existing))
            return RTC::PRECONDITION_NOT_MET;
    }
    RTC::ReturnCode_t result = RTC::RTC_OK;
    try {
        result = connector_profile.ports[0]->notify_connect(connector_profile);
    } catch (const CORBA::Exception &) {
        // A first port that cannot be reached: BAD_PARAMETER, as OpenRTM-aist answers.
        disconnect(id.c_str());
        return RTC::BAD_PARAMETER;
    }
    if (result != RTC::RTC_OK)
        withdraw(connector_profile);
    return result;
}

void PortBase::withdraw(const RTC::ConnectorProfile &profile)
{
    // A port further along may hold the connector although the chain failed: an OpenRTM-aist port
    // keeps it when its own subscription fails, and a port whose answer timed out may still have
    // made it. Each port is told; one that does not hold it answers BAD_PARAMETER, one that is gone
    // is passed over.
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i) {
        try {
            profile.ports[i]->notify_disconnect(profile.connector_id);
        } catch (const CORBA::Exception &) {
        }
    }
}

RTC::ReturnCode_t PortBase::disconnect(const char *connector_id)
{
    RTC::ConnectorProfile profile;
    if (!connector_id || !findProfile(connector_id, &profile))
        return RTC::BAD_PARAMETER;
    if (profile.ports.length() == 0)
        return notify_disconnect(connector_id);
    try {
        return profile.ports[0]->notify_disconnect(connector_id);
    } catch (const CORBA::Exception &) {
        // The first port's process is gone: disconnect our side anyway.
        callHook(ConnectionLost, profile);
        return notify_disconnect(connector_id);
    }
}

RTC::ReturnCode_t PortBase::disconnect_all()
{
    RTC::ConnectorProfileList profiles;
    {
        std::lock_guard lock(m_mutex);
        profiles = m_profile.connector_profiles;
    }
    RTC::ReturnCode_t result = RTC::RTC_OK;
    for (CORBA::ULong i = 0; i < profiles.length(); ++i) {
        if (disconnect(profiles[i].connector_id) != RTC::RTC_OK)
            result = RTC::RTC_ERROR;
    }
    return result;
}

RTC::ReturnCode_t PortBase::admit(const RTC::ConnectorProfile &profile)
{
    // `connection_limit` (OpenRTM-aist's CorbaPort property): negative or unset is unlimited.
    try {
        const std::string limit = portProperties().value("connection_limit");
        if (!limit.empty() && std::stol(limit) >= 0 && connectionCount() >= std::stoul(limit))
            return RTC::PRECONDITION_NOT_MET;
    } catch (const std::exception &) {
        // An unreadable limit is no limit, as in OpenRTM-aist.
    }
    const Properties connector = nvToProperties(profile.properties);
    const bool portAllows = portProperties().isYes("allow_dup_connection");
    if (connector.isYes("dataport.allow_dup_connection", portAllows))
        return RTC::RTC_OK;
    RTC::PortService_var self = reference();
    const std::unique_ptr<RTC::ConnectorProfileList> existing(get_connector_profiles());
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i) {
        if (self->_is_equivalent(profile.ports[i]))
            continue;
        for (CORBA::ULong c = 0; c < existing->length(); ++c) {
            const RTC::PortServiceList &ports = (*existing)[c].ports;
            for (CORBA::ULong p = 0; p < ports.length(); ++p) {
                if (ports[p]->_is_equivalent(profile.ports[i]))
                    return RTC::PRECONDITION_NOT_MET;
            }
        }
    }
    return RTC::RTC_OK;
}

RTC::ReturnCode_t PortBase::notify_connect(RTC::ConnectorProfile &connector_profile)
{
    observe(ConnectStep::NotifyConnect, connector_profile, RTC::RTC_OK);
    const RTC::ReturnCode_t result = connectSteps(connector_profile);
    observe(ConnectStep::Connected, connector_profile, result);
    return result;
}

RTC::ReturnCode_t PortBase::connectSteps(RTC::ConnectorProfile &connector_profile)
{
    if (const RTC::ReturnCode_t refused = admit(connector_profile); refused != RTC::RTC_OK)
        return refused;
    callHook(Publish, connector_profile);
    RTC::ReturnCode_t result = publishInterfaces(connector_profile);
    observe(ConnectStep::PublishInterfaces, connector_profile, result);
    if (result != RTC::RTC_OK)
        return result;
    const int index = ownIndex(connector_profile);
    if (index >= 0 && CORBA::ULong(index + 1) < connector_profile.ports.length()) {
        try {
            result = connector_profile.ports[index + 1]->notify_connect(connector_profile);
        } catch (const CORBA::Exception &) {
            result = RTC::RTC_ERROR;
        }
        observe(ConnectStep::ConnectNextPort, connector_profile, result);
    }
    if (result == RTC::RTC_OK) {
        callHook(Subscribe, connector_profile);
        result = subscribeInterfaces(connector_profile);
        observe(ConnectStep::SubscribeInterfaces, connector_profile, result);
    }
    if (result != RTC::RTC_OK) {
        unsubscribeInterfaces(connector_profile);
        return result;
    }
    storeProfile(connector_profile);
    callHook(Connected, connector_profile);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t PortBase::notify_disconnect(const char *connector_id)
{
    RTC::ConnectorProfile profile;
    if (!connector_id || !findProfile(connector_id, &profile))
        return RTC::BAD_PARAMETER;
    observe(ConnectStep::NotifyDisconnect, profile, RTC::RTC_OK);
    observe(ConnectStep::UnsubscribeInterfaces, profile, RTC::RTC_OK);
    callHook(Unsubscribe, profile);
    unsubscribeInterfaces(profile);
    eraseProfile(connector_id);
    // Pass it on; a dead port in the chain is skipped so the others still disconnect.
    const int index = ownIndex(profile);
    for (CORBA::ULong n = CORBA::ULong(index + 1); index >= 0 && n < profile.ports.length(); ++n) {
        try {
            const RTC::ReturnCode_t next = profile.ports[n]->notify_disconnect(connector_id);
            observe(ConnectStep::DisconnectNextPort, profile, next);
            break;
        } catch (const CORBA::Exception &) {
            callHook(ConnectionLost, profile);
        }
    }
    callHook(Disconnected, profile);
    observe(ConnectStep::Disconnected, profile, RTC::RTC_OK);
    return RTC::RTC_OK;
}

int PortBase::ownIndex(const RTC::ConnectorProfile &profile)
{
    RTC::PortService_var self = reference();
    for (CORBA::ULong i = 0; i < profile.ports.length(); ++i) {
        try {
            if (self->_is_equivalent(profile.ports[i]))
                return int(i);
        } catch (const CORBA::Exception &) {
        }
    }
    return -1;
}

bool PortBase::findProfile(const std::string &id, RTC::ConnectorProfile *profile)
{
    std::lock_guard lock(m_mutex);
    for (CORBA::ULong i = 0; i < m_profile.connector_profiles.length(); ++i) {
        if (id == static_cast<const char *>(m_profile.connector_profiles[i].connector_id)) {
            *profile = m_profile.connector_profiles[i];
            return true;
        }
    }
    return false;
}

void PortBase::storeProfile(const RTC::ConnectorProfile &profile)
{
    const std::string id(profile.connector_id);
    eraseProfile(id);
    std::lock_guard lock(m_mutex);
    const CORBA::ULong n = m_profile.connector_profiles.length();
    m_profile.connector_profiles.length(n + 1);
    m_profile.connector_profiles[n] = profile;
}

void PortBase::eraseProfile(const std::string &id)
{
    std::lock_guard lock(m_mutex);
    RTC::ConnectorProfileList kept;
    for (CORBA::ULong i = 0; i < m_profile.connector_profiles.length(); ++i) {
        if (id == static_cast<const char *>(m_profile.connector_profiles[i].connector_id))
            continue;
        const CORBA::ULong n = kept.length();
        kept.length(n + 1);
        kept[n] = m_profile.connector_profiles[i];
    }
    m_profile.connector_profiles = kept;
}

} // namespace Runtime
