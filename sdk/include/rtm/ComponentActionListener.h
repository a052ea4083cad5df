// SPDX-License-Identifier: MIT
// Listeners called around a component's actions, when ports are added or removed and when
// execution contexts are attached or detached.
#ifndef RTC_COMPONENTACTIONLISTENER_H
#define RTC_COMPONENTACTIONLISTENER_H

#include <rtm/ConnectorBase.h>
#include <rtm/ListenerHolder.h>
#include <rtm/RTC.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace RTC {
using UniqueId = ExecutionContextHandle_t;

/// Before which component action a PreComponentActionListener is called.
enum class PreComponentActionListenerType : uint8_t {
    PRE_ON_INITIALIZE,
    PRE_ON_FINALIZE,
    PRE_ON_STARTUP,
    PRE_ON_SHUTDOWN,
    PRE_ON_ACTIVATED,
    PRE_ON_DEACTIVATED,
    PRE_ON_ABORTING,
    PRE_ON_ERROR,
    PRE_ON_RESET,
    PRE_ON_EXECUTE,
    PRE_ON_STATE_UPDATE,
    PRE_ON_RATE_CHANGED,
    PRE_COMPONENT_ACTION_LISTENER_NUM
};

/// Called with the execution context's id (0 for on_initialize / on_finalize) before an action.
class PreComponentActionListener
{
public:
    static const char *toString(PreComponentActionListenerType type);
    virtual ~PreComponentActionListener();
    virtual void operator()(UniqueId ec_id) = 0;
};

/// After which component action a PostComponentActionListener is called.
enum class PostComponentActionListenerType : uint8_t {
    POST_ON_INITIALIZE,
    POST_ON_FINALIZE,
    POST_ON_STARTUP,
    POST_ON_SHUTDOWN,
    POST_ON_ACTIVATED,
    POST_ON_DEACTIVATED,
    POST_ON_ABORTING,
    POST_ON_ERROR,
    POST_ON_RESET,
    POST_ON_EXECUTE,
    POST_ON_STATE_UPDATE,
    POST_ON_RATE_CHANGED,
    POST_COMPONENT_ACTION_LISTENER_NUM
};

/// Called with the execution context's id and the action's result after an action.
class PostComponentActionListener
{
public:
    static const char *toString(PostComponentActionListenerType type);
    virtual ~PostComponentActionListener();
    virtual void operator()(UniqueId ec_id, ReturnCode_t ret) = 0;
};

/// Port events of a component.
enum class PortActionListenerType : uint8_t { ADD_PORT, REMOVE_PORT, PORT_ACTION_LISTENER_NUM };

/// Called with the profile of a port being added to or removed from the component.
class PortActionListener
{
public:
    static const char *toString(PortActionListenerType type);
    virtual ~PortActionListener();
    virtual void operator()(const ::RTC::PortProfile &pprof) = 0;
};

/// Execution context events of a component.
enum class ExecutionContextActionListenerType : uint8_t {
    EC_ATTACHED,
    EC_DETACHED,
    EC_ACTION_LISTENER_NUM
};

/// Called with the id under which an execution context was attached or is being detached.
class ExecutionContextActionListener
{
public:
    static const char *toString(ExecutionContextActionListenerType type);
    virtual ~ExecutionContextActionListener();
    virtual void operator()(UniqueId ec_id) = 0;
};

class PreComponentActionListenerHolder
    : public ::RTM::util::ListenerHolder<PreComponentActionListener>
{
public:
    PreComponentActionListenerHolder();
    ~PreComponentActionListenerHolder() override;
    void notify(UniqueId ec_id);
};

class PostComponentActionListenerHolder
    : public ::RTM::util::ListenerHolder<PostComponentActionListener>
{
public:
    PostComponentActionListenerHolder();
    ~PostComponentActionListenerHolder() override;
    void notify(UniqueId ec_id, ReturnCode_t ret);
};

class PortActionListenerHolder : public ::RTM::util::ListenerHolder<PortActionListener>
{
public:
    PortActionListenerHolder();
    ~PortActionListenerHolder() override;
    void notify(const RTC::PortProfile &pprofile);
};

class ExecutionContextActionListenerHolder
    : public ::RTM::util::ListenerHolder<ExecutionContextActionListener>
{
public:
    ExecutionContextActionListenerHolder();
    ~ExecutionContextActionListenerHolder() override;
    void notify(UniqueId ec_id);
};

/// A component's action listeners, one holder per event.
class ComponentActionListeners
{
public:
    ComponentActionListeners();
    ~ComponentActionListeners();
    bool addListener(PreComponentActionListenerType type, PreComponentActionListener *listener,
                     bool autoclean);
    bool addListener(PostComponentActionListenerType type, PostComponentActionListener *listener,
                     bool autoclean);
    bool addListener(PortActionListenerType type, PortActionListener *listener, bool autoclean);
    bool addListener(ExecutionContextActionListenerType type,
                     ExecutionContextActionListener *listener, bool autoclean);
    bool removeListener(PreComponentActionListenerType type, PreComponentActionListener *listener);
    bool removeListener(PostComponentActionListenerType type,
                        PostComponentActionListener *listener);
    bool removeListener(PortActionListenerType type, PortActionListener *listener);
    bool removeListener(ExecutionContextActionListenerType type,
                        ExecutionContextActionListener *listener);
    bool notify(PreComponentActionListenerType type, UniqueId ec_id);
    bool notify(PostComponentActionListenerType type, UniqueId ec_id, ReturnCode_t ret);
    bool notify(PortActionListenerType type, const RTC::PortProfile &pprofile);
    bool notify(ExecutionContextActionListenerType type, UniqueId ec_id);

private:
    std::array<PreComponentActionListenerHolder,
               static_cast<uint8_t>(
                   PreComponentActionListenerType::PRE_COMPONENT_ACTION_LISTENER_NUM)>
        preaction_;
    std::array<PostComponentActionListenerHolder,
               static_cast<uint8_t>(
                   PostComponentActionListenerType::POST_COMPONENT_ACTION_LISTENER_NUM)>
        postaction_;
    std::array<PortActionListenerHolder,
               static_cast<uint8_t>(PortActionListenerType::PORT_ACTION_LISTENER_NUM)>
        portaction_;
    std::array<ExecutionContextActionListenerHolder,
               static_cast<uint8_t>(ExecutionContextActionListenerType::EC_ACTION_LISTENER_NUM)>
        ecaction_;
};
} // namespace RTC

#endif // RTC_COMPONENTACTIONLISTENER_H
