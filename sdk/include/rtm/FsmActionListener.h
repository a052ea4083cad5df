// SPDX-License-Identifier: MIT
// Listeners of an FSM component's state actions (RTObject_impl::addPreFsmActionListener and
// addPostFsmActionListener), called with the name of the state concerned.
#ifndef RTM_FSMACTIONLISTENER_H
#define RTM_FSMACTIONLISTENER_H

#include <rtm/ListenerHolder.h>
#include <rtm/RTC.h>
#include <rtm/idl/ExtendedFsmServiceStub.h>

#include <algorithm>
#include <array>
#include <assert.h>
#include <cassert>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <cwctype>
#include <fstream>
#include <functional>
#include <ios>
#include <iostream>
#include <istream>
#include <mutex>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <utility>
#include <vector>
#include <wctype.h>

namespace RTC
{
/// Points before a state action at which PreFsmActionListeners are called.
enum class PreFsmActionListenerType : uint8_t
{
    PRE_ON_INIT,
    PRE_ON_ENTRY,
    PRE_ON_DO,
    PRE_ON_EXIT,
    PRE_ON_STATE_CHANGE,
    PRE_FSM_ACTION_LISTENER_NUM
};

/// Called before a state's init, entry, do or exit action, or before the state is left.
class PreFsmActionListener
{
public:
    static const char *toString(PreFsmActionListenerType type)
    {
        static const char *const names[] = {"PRE_ON_INIT", "PRE_ON_ENTRY", "PRE_ON_DO", "PRE_ON_EXIT",
                                            "PRE_ON_STATE_CHANGE", "PRE_FSM_ACTION_LISTENER_NUM"};
        return type <= PreFsmActionListenerType::PRE_FSM_ACTION_LISTENER_NUM ? names[static_cast<uint8_t>(type)]
                                                                              : "";
    }
    virtual ~PreFsmActionListener() {}
    /// @p state is the name of the state (its class name).
    virtual void operator()(const char *state) = 0;
};

/// Points after a state action at which PostFsmActionListeners are called.
enum class PostFsmActionListenerType : uint8_t
{
    POST_ON_INIT,
    POST_ON_ENTRY,
    POST_ON_DO,
    POST_ON_EXIT,
    POST_ON_STATE_CHANGE,
    POST_FSM_ACTION_LISTENER_NUM
};

/// Called after a state's init, entry, do or exit action (with its result), or once the state is entered.
class PostFsmActionListener
{
public:
    static const char *toString(PostFsmActionListenerType type)
    {
        static const char *const names[] = {"POST_ON_INIT", "POST_ON_ENTRY", "POST_ON_DO", "POST_ON_EXIT",
                                            "POST_ON_STATE_CHANGE", "POST_FSM_ACTION_LISTENER_NUM"};
        return type <= PostFsmActionListenerType::POST_FSM_ACTION_LISTENER_NUM ? names[static_cast<uint8_t>(type)]
                                                                                : "";
    }
    virtual ~PostFsmActionListener() {}
    virtual void operator()(const char *state, ReturnCode_t ret) = 0;
};

/// Changes of a component's FSM profile at which FsmProfileListeners are called.
enum class FsmProfileListenerType : uint8_t
{
    SET_FSM_PROFILE,
    GET_FSM_PROFILE,
    ADD_FSM_STATE,
    REMOVE_FSM_STATE,
    ADD_FSM_TRANSITION,
    REMOVE_FSM_TRANSITION,
    BIND_FSM_EVENT,
    UNBIND_FSM_EVENT,
    FSM_PROFILE_LISTENER_NUM
};

/// Called with the FSM profile when it is set, read or changed.
class FsmProfileListener
{
public:
    static const char *toString(FsmProfileListenerType type);
    virtual ~FsmProfileListener();
    virtual void operator()(const ::RTC::FsmProfile &fsmprof) = 0;
};

/// Accesses to a component's FSM structure at which FsmStructureListeners are called.
enum class FsmStructureListenerType : uint8_t
{
    SET_FSM_STRUCTURE,
    GET_FSM_STRUCTURE,
    FSM_STRUCTURE_LISTENER_NUM
};

/// Called with the FSM structure when it is set or read (a listener may change what is read).
class FsmStructureListener
{
public:
    static const char *toString(FsmStructureListenerType type);
    virtual ~FsmStructureListener();
    virtual void operator()(::RTC::FsmStructure &pprof) = 0;
};

class PreFsmActionListenerHolder : public ::RTM::util::ListenerHolder<PreFsmActionListener>
{
public:
    PreFsmActionListenerHolder();
    ~PreFsmActionListenerHolder() override;
    void notify(const char *state);
};

class PostFsmActionListenerHolder : public ::RTM::util::ListenerHolder<PostFsmActionListener>
{
public:
    PostFsmActionListenerHolder();
    ~PostFsmActionListenerHolder() override;
    void notify(const char *state, ReturnCode_t ret);
};

class FsmProfileListenerHolder : public ::RTM::util::ListenerHolder<FsmProfileListener>
{
public:
    FsmProfileListenerHolder();
    ~FsmProfileListenerHolder() override;
    void notify(RTC::FsmProfile &profile);
};

class FsmStructureListenerHolder : public ::RTM::util::ListenerHolder<FsmStructureListener>
{
public:
    FsmStructureListenerHolder();
    ~FsmStructureListenerHolder() override;
    void notify(RTC::FsmStructure &structure);
};

/**
 * An FSM component's listeners, one holder per event. Each call with a type out of range (a
 * *_NUM sentinel) does nothing and answers false.
 */
class FsmActionListeners
{
public:
    FsmActionListeners();
    ~FsmActionListeners();

    bool addListener(PreFsmActionListenerType type, PreFsmActionListener *listener, bool autoclean = true);
    bool removeListener(PreFsmActionListenerType type, PreFsmActionListener *listener);
    bool addListener(PostFsmActionListenerType type, PostFsmActionListener *listener, bool autoclean = true);
    bool removeListener(PostFsmActionListenerType type, PostFsmActionListener *listener);
    bool addListener(FsmProfileListenerType type, FsmProfileListener *listener, bool autoclean = true);
    bool removeListener(FsmProfileListenerType type, FsmProfileListener *listener);
    bool addListener(FsmStructureListenerType type, FsmStructureListener *listener, bool autoclean = true);
    bool removeListener(FsmStructureListenerType type, FsmStructureListener *listener);
    bool notify(PreFsmActionListenerType type, const char *state);
    bool notify(PostFsmActionListenerType type, const char *state, ReturnCode_t ret);
    bool notify(FsmProfileListenerType type, RTC::FsmProfile &profile);
    bool notify(FsmStructureListenerType type, RTC::FsmStructure &structure);

private:
    std::array<PreFsmActionListenerHolder,
               static_cast<uint8_t>(PreFsmActionListenerType::PRE_FSM_ACTION_LISTENER_NUM)>
        preaction_;
    std::array<PostFsmActionListenerHolder,
               static_cast<uint8_t>(PostFsmActionListenerType::POST_FSM_ACTION_LISTENER_NUM)>
        postaction_;
    std::array<FsmProfileListenerHolder, static_cast<uint8_t>(FsmProfileListenerType::FSM_PROFILE_LISTENER_NUM)>
        profile_;
    std::array<FsmStructureListenerHolder,
               static_cast<uint8_t>(FsmStructureListenerType::FSM_STRUCTURE_LISTENER_NUM)>
        structure_;
};
} // namespace RTC

#endif // RTM_FSMACTIONLISTENER_H
