// SPDX-License-Identifier: MIT
// The component action listeners and the port connect listeners.
#include <rtm/ComponentActionListener.h>
#include <rtm/PortConnectListener.h>

namespace RTC {

namespace {

template<typename Enum, size_t N> const char *nameOf(Enum type, const char *const (&names)[N])
{
    const size_t index = static_cast<size_t>(type);
    return index < N ? names[index] : "";
}

// Holder index of a listener type; false for the *_NUM sentinels and beyond.
template<typename Holders, typename Enum> bool validIndex(const Holders &holders, Enum type)
{
    return static_cast<size_t>(type) < holders.size();
}

} // namespace

// --- port connect listeners ---

const char *PortConnectListener::toString(PortConnectListenerType type)
{
    static const char *const names[] = {"ON_NOTIFY_CONNECT", "ON_NOTIFY_DISCONNECT",
                                        "ON_UNSUBSCRIBE_INTERFACES", "PORT_CONNECT_LISTENER_NUM"};
    return nameOf(type, names);
}

PortConnectListener::~PortConnectListener() = default;

const char *PortConnectRetListener::toString(PortConnectRetListenerType type)
{
    static const char *const names[] = {"ON_PUBLISH_INTERFACES",        "ON_CONNECT_NEXTPORT",
                                        "ON_SUBSCRIBE_INTERFACES",      "ON_CONNECTED",
                                        "ON_DISCONNECT_NEXT",           "ON_DISCONNECTED",
                                        "PORT_CONNECT_RET_LISTENER_NUM"};
    return nameOf(type, names);
}

PortConnectRetListener::~PortConnectRetListener() = default;

PortConnectListenerHolder::PortConnectListenerHolder() = default;
PortConnectListenerHolder::~PortConnectListenerHolder() = default;

void PortConnectListenerHolder::notify(const char *portname, RTC::ConnectorProfile &profile)
{
    LISTENERHOLDER_CALLBACK(operator(), (portname, profile));
}

PortConnectRetListenerHolder::PortConnectRetListenerHolder() = default;
PortConnectRetListenerHolder::~PortConnectRetListenerHolder() = default;

void PortConnectRetListenerHolder::notify(const char *portname, RTC::ConnectorProfile &profile,
                                          ReturnCode_t ret)
{
    LISTENERHOLDER_CALLBACK(operator(), (portname, profile, ret));
}

PortConnectListeners::PortConnectListeners() = default;
PortConnectListeners::~PortConnectListeners() = default;

bool PortConnectListeners::addListener(PortConnectListenerType type, PortConnectListener *listener,
                                       bool autoclean)
{
    if (!validIndex(portconnect_, type))
        return false;
    portconnect_[static_cast<size_t>(type)].addListener(listener, autoclean);
    return true;
}

bool PortConnectListeners::removeListener(PortConnectListenerType type,
                                          PortConnectListener *listener)
{
    if (!validIndex(portconnect_, type))
        return false;
    portconnect_[static_cast<size_t>(type)].removeListener(listener);
    return true;
}

bool PortConnectListeners::addListener(PortConnectRetListenerType type,
                                       PortConnectRetListener *listener, bool autoclean)
{
    if (!validIndex(portconnret_, type))
        return false;
    portconnret_[static_cast<size_t>(type)].addListener(listener, autoclean);
    return true;
}

bool PortConnectListeners::removeListener(PortConnectRetListenerType type,
                                          PortConnectRetListener *listener)
{
    if (!validIndex(portconnret_, type))
        return false;
    portconnret_[static_cast<size_t>(type)].removeListener(listener);
    return true;
}

bool PortConnectListeners::notify(PortConnectListenerType type, const char *portname,
                                  RTC::ConnectorProfile &profile)
{
    if (!validIndex(portconnect_, type))
        return false;
    portconnect_[static_cast<size_t>(type)].notify(portname, profile);
    return true;
}

bool PortConnectListeners::notify(PortConnectRetListenerType type, const char *portname,
                                  RTC::ConnectorProfile &profile, ReturnCode_t ret)
{
    if (!validIndex(portconnret_, type))
        return false;
    portconnret_[static_cast<size_t>(type)].notify(portname, profile, ret);
    return true;
}

// --- component action listeners ---

const char *PreComponentActionListener::toString(PreComponentActionListenerType type)
{
    static const char *const names[] = {"PRE_ON_INITIALIZE",
                                        "PRE_ON_FINALIZE",
                                        "PRE_ON_STARTUP",
                                        "PRE_ON_SHUTDOWN",
                                        "PRE_ON_ACTIVATED",
                                        "PRE_ON_DEACTIVATED",
                                        "PRE_ON_ABORTING",
                                        "PRE_ON_ERROR",
                                        "PRE_ON_RESET",
                                        "PRE_ON_EXECUTE",
                                        "PRE_ON_STATE_UPDATE",
                                        "PRE_ON_RATE_CHANGED",
                                        "PRE_COMPONENT_ACTION_LISTENER_NUM"};
    return nameOf(type, names);
}

PreComponentActionListener::~PreComponentActionListener() = default;

const char *PostComponentActionListener::toString(PostComponentActionListenerType type)
{
    static const char *const names[] = {"POST_ON_INITIALIZE",
                                        "POST_ON_FINALIZE",
                                        "POST_ON_STARTUP",
                                        "POST_ON_SHUTDOWN",
                                        "POST_ON_ACTIVATED",
                                        "POST_ON_DEACTIVATED",
                                        "POST_ON_ABORTING",
                                        "POST_ON_ERROR",
                                        "POST_ON_RESET",
                                        "POST_ON_EXECUTE",
                                        "POST_ON_STATE_UPDATE",
                                        "POST_ON_RATE_CHANGED",
                                        "POST_COMPONENT_ACTION_LISTENER_NUM"};
    return nameOf(type, names);
}

PostComponentActionListener::~PostComponentActionListener() = default;

const char *PortActionListener::toString(PortActionListenerType type)
{
    static const char *const names[] = {"ADD_PORT", "REMOVE_PORT", "PORT_ACTION_LISTENER_NUM"};
    return nameOf(type, names);
}

PortActionListener::~PortActionListener() = default;

const char *ExecutionContextActionListener::toString(ExecutionContextActionListenerType type)
{
    static const char *const names[] = {"ATTACH_EC", "DETACH_EC", "EC_ACTION_LISTENER_NUM"};
    return nameOf(type, names);
}

ExecutionContextActionListener::~ExecutionContextActionListener() = default;

PreComponentActionListenerHolder::PreComponentActionListenerHolder() = default;
PreComponentActionListenerHolder::~PreComponentActionListenerHolder() = default;
void PreComponentActionListenerHolder::notify(UniqueId ec_id)
{
    LISTENERHOLDER_CALLBACK(operator(), (ec_id));
}

PostComponentActionListenerHolder::PostComponentActionListenerHolder() = default;
PostComponentActionListenerHolder::~PostComponentActionListenerHolder() = default;
void PostComponentActionListenerHolder::notify(UniqueId ec_id, ReturnCode_t ret)
{
    LISTENERHOLDER_CALLBACK(operator(), (ec_id, ret));
}

PortActionListenerHolder::PortActionListenerHolder() = default;
PortActionListenerHolder::~PortActionListenerHolder() = default;
void PortActionListenerHolder::notify(const RTC::PortProfile &pprofile)
{
    LISTENERHOLDER_CALLBACK(operator(), (pprofile));
}

ExecutionContextActionListenerHolder::ExecutionContextActionListenerHolder() = default;
ExecutionContextActionListenerHolder::~ExecutionContextActionListenerHolder() = default;
void ExecutionContextActionListenerHolder::notify(UniqueId ec_id)
{
    LISTENERHOLDER_CALLBACK(operator(), (ec_id));
}

ComponentActionListeners::ComponentActionListeners() = default;
ComponentActionListeners::~ComponentActionListeners() = default;

namespace {

template<typename Holders, typename Enum, typename Listener>
bool addTo(Holders &holders, Enum type, Listener *listener, bool autoclean)
{
    if (!validIndex(holders, type))
        return false;
    holders[static_cast<size_t>(type)].addListener(listener, autoclean);
    return true;
}

template<typename Holders, typename Enum, typename Listener>
bool removeFrom(Holders &holders, Enum type, Listener *listener)
{
    if (!validIndex(holders, type))
        return false;
    holders[static_cast<size_t>(type)].removeListener(listener);
    return true;
}

} // namespace

bool ComponentActionListeners::addListener(PreComponentActionListenerType type,
                                           PreComponentActionListener *listener, bool autoclean)
{
    return addTo(preaction_, type, listener, autoclean);
}

bool ComponentActionListeners::addListener(PostComponentActionListenerType type,
                                           PostComponentActionListener *listener, bool autoclean)
{
    return addTo(postaction_, type, listener, autoclean);
}

bool ComponentActionListeners::addListener(PortActionListenerType type,
                                           PortActionListener *listener, bool autoclean)
{
    return addTo(portaction_, type, listener, autoclean);
}

bool ComponentActionListeners::addListener(ExecutionContextActionListenerType type,
                                           ExecutionContextActionListener *listener, bool autoclean)
{
    return addTo(ecaction_, type, listener, autoclean);
}

bool ComponentActionListeners::removeListener(PreComponentActionListenerType type,
                                              PreComponentActionListener *listener)
{
    return removeFrom(preaction_, type, listener);
}

bool ComponentActionListeners::removeListener(PostComponentActionListenerType type,
                                              PostComponentActionListener *listener)
{
    return removeFrom(postaction_, type, listener);
}

bool ComponentActionListeners::removeListener(PortActionListenerType type,
                                              PortActionListener *listener)
{
    return removeFrom(portaction_, type, listener);
}

bool ComponentActionListeners::removeListener(ExecutionContextActionListenerType type,
                                              ExecutionContextActionListener *listener)
{
    return removeFrom(ecaction_, type, listener);
}

bool ComponentActionListeners::notify(PreComponentActionListenerType type, UniqueId ec_id)
{
    if (!validIndex(preaction_, type))
        return false;
    preaction_[static_cast<size_t>(type)].notify(ec_id);
    return true;
}

bool ComponentActionListeners::notify(PostComponentActionListenerType type, UniqueId ec_id,
                                      ReturnCode_t ret)
{
    if (!validIndex(postaction_, type))
        return false;
    postaction_[static_cast<size_t>(type)].notify(ec_id, ret);
    return true;
}

bool ComponentActionListeners::notify(PortActionListenerType type, const RTC::PortProfile &pprofile)
{
    if (!validIndex(portaction_, type))
        return false;
    portaction_[static_cast<size_t>(type)].notify(pprofile);
    return true;
}

bool ComponentActionListeners::notify(ExecutionContextActionListenerType type, UniqueId ec_id)
{
    if (!validIndex(ecaction_, type))
        return false;
    ecaction_[static_cast<size_t>(type)].notify(ec_id);
    return true;
}

} // namespace RTC
