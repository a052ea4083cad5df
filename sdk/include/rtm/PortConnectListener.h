// SPDX-License-Identifier: MIT
// Listeners a component's ports call at each step of connecting and disconnecting.
#ifndef RTC_PORTCONNECTLISTENER_H
#define RTC_PORTCONNECTLISTENER_H

#include <rtm/ListenerHolder.h>
#include <rtm/RTC.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace RTC {
/// Steps of notify_connect / notify_disconnect that have no result.
enum class PortConnectListenerType : uint8_t {
    ON_NOTIFY_CONNECT, ///< notify_connect arrived at the port
    ON_NOTIFY_DISCONNECT, ///< notify_disconnect arrived for a connector the port holds
    ON_UNSUBSCRIBE_INTERFACES, ///< the port is about to drop the connector's interfaces
    PORT_CONNECT_LISTENER_NUM
};

/// Called with the port's name and the connector profile at a PortConnectListenerType step.
class PortConnectListener
{
public:
    static const char *toString(PortConnectListenerType type);
    virtual ~PortConnectListener();
    virtual void operator()(const char *portname, RTC::ConnectorProfile &profile) = 0;
};

/// Steps of notify_connect / notify_disconnect that have a result.
enum class PortConnectRetListenerType : uint8_t {
    ON_PUBLISH_INTERFACES, ///< the port published its interfaces
    ON_CONNECT_NEXTPORT, ///< the next port of the connector answered notify_connect
    ON_SUBSCRIBE_INTERFACES, ///< the port subscribed to the others' interfaces
    ON_CONNECTED, ///< notify_connect ends
    ON_DISCONNECT_NEXT, ///< the next port of the connector answered notify_disconnect
    ON_DISCONNECTED, ///< notify_disconnect ends
    PORT_CONNECT_RET_LISTENER_NUM
};

/// Called with the port's name, the connector profile and the step's result.
class PortConnectRetListener
{
public:
    static const char *toString(PortConnectRetListenerType type);
    virtual ~PortConnectRetListener();
    virtual void operator()(const char *portname, RTC::ConnectorProfile &profile, ReturnCode_t ret)
        = 0;
};

/// The PortConnectListeners of one step.
class PortConnectListenerHolder : public ::RTM::util::ListenerHolder<PortConnectListener>
{
public:
    PortConnectListenerHolder();
    ~PortConnectListenerHolder() override;
    void notify(const char *portname, RTC::ConnectorProfile &profile);
};

/// The PortConnectRetListeners of one step.
class PortConnectRetListenerHolder : public ::RTM::util::ListenerHolder<PortConnectRetListener>
{
public:
    PortConnectRetListenerHolder();
    ~PortConnectRetListenerHolder() override;
    void notify(const char *portname, RTC::ConnectorProfile &profile, ReturnCode_t ret);
};

/// A component's port connect listeners, one holder per step; every port of the component calls
/// them.
class PortConnectListeners
{
public:
    PortConnectListeners();
    ~PortConnectListeners();
    bool addListener(PortConnectListenerType type, PortConnectListener *listener,
                     bool autoclean = true);
    bool removeListener(PortConnectListenerType type, PortConnectListener *listener);
    bool addListener(PortConnectRetListenerType type, PortConnectRetListener *listener,
                     bool autoclean = true);
    bool removeListener(PortConnectRetListenerType type, PortConnectRetListener *listener);
    bool notify(PortConnectListenerType type, const char *portname, RTC::ConnectorProfile &profile);
    bool notify(PortConnectRetListenerType type, const char *portname,
                RTC::ConnectorProfile &profile, ReturnCode_t ret);

private:
    std::array<PortConnectListenerHolder,
               static_cast<uint8_t>(PortConnectListenerType::PORT_CONNECT_LISTENER_NUM)>
        portconnect_;
    std::array<PortConnectRetListenerHolder,
               static_cast<uint8_t>(PortConnectRetListenerType::PORT_CONNECT_RET_LISTENER_NUM)>
        portconnret_;
};
} // namespace RTC

#endif // RTC_PORTCONNECTLISTENER_H
