// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <RTC.hh>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace RTC {
class DirectPortBase;
class PortConnectListeners;
} // namespace RTC

namespace Runtime {

/// The steps of the connect and disconnect protocol a port reports to its ConnectObserver.
enum class ConnectStep : uint8_t {
    NotifyConnect,         ///< notify_connect arrived (before anything is checked)
    PublishInterfaces,     ///< this port published its interfaces (with the result)
    ConnectNextPort,       ///< the next port of the chain answered (with its result)
    SubscribeInterfaces,   ///< this port subscribed to the others' interfaces (with the result)
    Connected,             ///< notify_connect ends (with its result)
    NotifyDisconnect,      ///< notify_disconnect arrived for a connector this port holds
    UnsubscribeInterfaces, ///< this port is about to drop the connector's interfaces
    DisconnectNextPort,    ///< the next port of the chain was told (with the result)
    Disconnected           ///< notify_disconnect ends (with its result)
};

/**
 * Called at each ConnectStep with the connector profile as it stands and the step's result
 * (RTC_OK for steps without one). The SDK turns these into OpenRTM-aist's port connect listeners.
 */
using ConnectObserver = std::function<void(ConnectStep, RTC::ConnectorProfile &, RTC::ReturnCode_t)>;

/**
 * RTC::PortService as OpenRTM-aist implements it. connect() gives the profile an id and starts the
 * notify_connect chain at ports[0]; each port publishes its interfaces (adds IOR keys), passes the
 * profile on to the next port, then subscribes to what the later ports published and stores the
 * profile. Subclasses say what they publish and subscribe.
 */
class PortBase : public virtual POA_RTC::PortService
{
public:
    explicit PortBase(const std::string &name);
    ~PortBase() override;

    /// Short name (`out`); the profile name is `<instance>.<name>`.
    const std::string &name() const { return m_name; }
    /// Sets the owner and the profile name; called when the component adds the port.
    void setOwner(RTC::RTObject_ptr owner, const std::string &instanceName);
    /// Port profile properties (`port.port_type`, `dataport.*`).
    void setProperty(const std::string &key, const std::string &value);
    /// This port's object reference (activates the servant in the root POA on first use).
    RTC::PortService_ptr reference();
    /// The name the port was made with, without the instance name.
    const std::string &shortName() const { return m_name; }
    /// Profile name `<instance>.<port>`.
    std::string profileName();
    /// Number of stored connections.
    size_t connectionCount();
    /// Reports the steps of notify_connect / notify_disconnect to @p observer (empty: nobody).
    void setConnectObserver(ConnectObserver observer);

    // OpenRTM-aist's PortBase accessors, which component code calls on RTC::PortBase.
    /// The profile name: `<instance>.<port>` once the component added the port.
    const char *getName() const;
    /// The port profile itself (not a copy); connector profiles change as connections come and go.
    const RTC::PortProfile &getPortProfile() const;
    const RTC::PortProfile &getProfile() const { return getPortProfile(); }
    /// This port's object reference, not duplicated (nil before the port is activated).
    RTC::PortService_ptr getPortRef() const;
    /// Sets the name the port profile shows (`instance.port`), as OpenRTM-aist's setName.
    void setName(const char *name);
    /**
     * The port's reference is its servant's own (reference()): @p port_ref must be that one;
     * another is refused with a message (the port keeps its own).
     */
    void setPortRef(RTC::PortService_ptr port_ref);
    /// The port as an in-process sender or receiver of samples (typed data ports); null otherwise.
    virtual RTC::DirectPortBase *getDirectPort() { return nullptr; }
    /**
     * Calls @p portconnListeners (not owned) at each step of connecting and disconnecting this
     * port, as a component does for its ports. Defined by the component SDK, which has the type.
     */
    void setPortConnectListenerHolder(RTC::PortConnectListeners *portconnListeners);

    /**
     * OpenRTM-aist's PortBase callbacks, objects with `operator()(RTC::ConnectorProfile &)`
     * (RTC::ConnectionCallback), not owned; null removes one. OnPublishInterfaces and
     * OnSubscribeInterfaces come before the port publishes / subscribes, OnConnected after a
     * connection is stored, OnUnsubscribeInterfaces before the port drops a connection's
     * interfaces, OnDisconnected after it is gone, OnConnectionLost when a port of the
     * connection could not be reached while disconnecting.
     */
    template<class Callback> void setOnPublishInterfaces(Callback *on_publish)
    {
        setCallback(Hook::Publish, on_publish);
    }
    void setOnPublishInterfaces(std::nullptr_t) { clearCallback(Hook::Publish); }
    template<class Callback> void setOnSubscribeInterfaces(Callback *on_subscribe)
    {
        setCallback(Hook::Subscribe, on_subscribe);
    }
    void setOnSubscribeInterfaces(std::nullptr_t) { clearCallback(Hook::Subscribe); }
    template<class Callback> void setOnConnected(Callback *on_connected)
    {
        setCallback(Hook::Connected, on_connected);
    }
    void setOnConnected(std::nullptr_t) { clearCallback(Hook::Connected); }
    template<class Callback> void setOnUnsubscribeInterfaces(Callback *on_unsubscribe)
    {
        setCallback(Hook::Unsubscribe, on_unsubscribe);
    }
    void setOnUnsubscribeInterfaces(std::nullptr_t) { clearCallback(Hook::Unsubscribe); }
    template<class Callback> void setOnDisconnected(Callback *on_disconnected)
    {
        setCallback(Hook::Disconnected, on_disconnected);
    }
    void setOnDisconnected(std::nullptr_t) { clearCallback(Hook::Disconnected); }
    template<class Callback> void setOnConnectionLost(Callback *on_connection_lost)
    {
        setCallback(Hook::ConnectionLost, on_connection_lost);
    }
    void setOnConnectionLost(std::nullptr_t) { clearCallback(Hook::ConnectionLost); }
    /// Lets others reach what the port provides (service providers); called when the component
    /// is activated, as OpenRTM-aist's PortAdmin::activatePorts.
    virtual void activateInterfaces() {}
    /// Makes what the port provides unreachable until the next activation; called when the
    /// component is deactivated.
    virtual void deactivateInterfaces() {}
    /// Withdraws and drops what the port provides, for good; called when the port is removed or
    /// the component finalizes.
    virtual void releaseInterfaces() {}

    RTC::PortProfile *get_port_profile() override;
    RTC::ConnectorProfileList *get_connector_profiles() override;
    RTC::ConnectorProfile *get_connector_profile(const char *connector_id) override;
    RTC::ReturnCode_t connect(RTC::ConnectorProfile &connector_profile) override;
    RTC::ReturnCode_t disconnect(const char *connector_id) override;
    RTC::ReturnCode_t disconnect_all() override;
    RTC::ReturnCode_t notify_connect(RTC::ConnectorProfile &connector_profile) override;
    RTC::ReturnCode_t notify_disconnect(const char *connector_id) override;

protected:
    /**
     * Whether this port takes the connection @p profile describes, checked before anything is
     * set up, as OpenRTM-aist's ports do: a second connection to a port this one is already
     * connected to is refused with PRECONDITION_NOT_MET unless the connector's
     * `dataport.allow_dup_connection` (else the port's `allow_dup_connection`) is YES.
     */
    virtual RTC::ReturnCode_t admit(const RTC::ConnectorProfile &profile);
    /// Adds this port's own interface keys to @p profile.
    virtual RTC::ReturnCode_t publishInterfaces(RTC::ConnectorProfile &profile) = 0;
    /// Connects to what the other ports published in @p profile.
    virtual RTC::ReturnCode_t subscribeInterfaces(const RTC::ConnectorProfile &profile) = 0;
    /// Drops what publish/subscribe set up for the connector.
    virtual void unsubscribeInterfaces(const RTC::ConnectorProfile &profile) = 0;
    /// Adds an interface entry to the port profile (service ports).
    void addInterfaceProfile(const std::string &instanceName, const std::string &typeName, bool provided);
    /// Port profile properties as given so far.
    Properties portProperties();

private:
    enum Hook { Publish, Subscribe, Connected, Unsubscribe, Disconnected, ConnectionLost, HookCount };
    using HookFunction = std::function<void(RTC::ConnectorProfile &)>;
    template<class Callback> void setCallback(Hook hook, Callback *callback)
    {
        HookFunction function;
        if (callback != nullptr)
            function = [callback](RTC::ConnectorProfile &profile) { (*callback)(profile); };
        std::lock_guard<std::mutex> lock(m_mutex);
        m_hooks[hook] = function;
    }
    void clearCallback(Hook hook)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_hooks[hook] = HookFunction();
    }
    /// Tells every port of a connector that failed to be made to drop it.
    void withdraw(const RTC::ConnectorProfile &profile);
    void callHook(Hook hook, RTC::ConnectorProfile &profile);
    RTC::ReturnCode_t connectSteps(RTC::ConnectorProfile &connector_profile);
    int ownIndex(const RTC::ConnectorProfile &profile);
    bool findProfile(const std::string &id, RTC::ConnectorProfile *profile);
    void storeProfile(const RTC::ConnectorProfile &profile);
    void eraseProfile(const std::string &id);
    void observe(ConnectStep step, RTC::ConnectorProfile &profile, RTC::ReturnCode_t result);

    std::string m_name;
    mutable std::mutex m_mutex;
    RTC::PortProfile m_profile;
    RTC::PortService_var m_self;
    ConnectObserver m_observer;
    HookFunction m_hooks[HookCount];
};

/**
 * True when two data type names denote the same type (`IDL:RTC/TimedLong:1.0`, `RTC::TimedLong`,
 * `TimedLong`), or when either is "any" (the data type of ports that take samples of every type,
 * such as an FSM component's EventInPort).
 */
bool sameDataType(const std::string &a, const std::string &b);

} // namespace Runtime
