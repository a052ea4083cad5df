// SPDX-License-Identifier: MIT
// Listeners of an FSM component's state actions (RTObject_impl::addPreFsmActionListener and
// addPostFsmActionListener), called with the name of the state concerned.
#ifndef RTM_FSMACTIONLISTENER_H
#define RTM_FSMACTIONLISTENER_H

#include <rtm/RTC.h>

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
} // namespace RTC

#endif // RTM_FSMACTIONLISTENER_H
