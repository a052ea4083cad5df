// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/ManagerActionListener.h>

#include "listenerset.h"

#include <mutex>

namespace Runtime {
class Manager;
}

namespace RTC::Sdk {

/// The RTM:: action listeners of the manager, called from the runtime's hooks and from RTC::Manager.
class ManagerActions
{
public:
    /// Routes @p runtime's creation and naming steps to the listeners.
    void install(Runtime::Manager &runtime);

    std::recursive_mutex mutex;
    ListenerSet<RTM::ManagerActionListener> manager;
    ListenerSet<RTM::ModuleActionListener> module;
    ListenerSet<RTM::RtcLifecycleActionListener> lifecycle;
    ListenerSet<RTM::NamingActionListener> naming;
    ListenerSet<RTM::LocalServiceActionListener> localService;

    template <typename Listener>
    void add(ListenerSet<Listener> &set, Listener *listener, bool autoclean)
    {
        std::lock_guard<std::recursive_mutex> lock(mutex);
        set.add(listener, autoclean);
    }
    template <typename Listener>
    void remove(ListenerSet<Listener> &set, Listener *listener)
    {
        std::lock_guard<std::recursive_mutex> lock(mutex);
        set.remove(listener);
    }

    /// Calls @p call on each listener of @p set under the lock.
    template <typename Listener, typename Call>
    void each(ListenerSet<Listener> &set, Call call)
    {
        std::lock_guard<std::recursive_mutex> lock(mutex);
        set.forEach(call);
    }
};

} // namespace RTC::Sdk
