// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/RTObject.h>

#include "listenerset.h"

#include <mutex>
#include <string>

namespace RTC {

/// A component's FSM action listeners and its current FSM state.
struct RTObject_impl::FsmActions
{
    static const size_t kinds = size_t(PreFsmActionListenerType::PRE_FSM_ACTION_LISTENER_NUM);
    static_assert(kinds == size_t(PostFsmActionListenerType::POST_FSM_ACTION_LISTENER_NUM),
                  "one post kind for each pre kind");

    mutable std::mutex mutex;
    Sdk::ListenerSet<PreFsmActionListener> pre[kinds];
    Sdk::ListenerSet<PostFsmActionListener> post[kinds];
    std::string state;
};

} // namespace RTC
