// SPDX-License-Identifier: MIT
#pragma once

// Helpers of the "…Listeners" classes, which keep one ListenerHolder per listener type in a
// std::array indexed by the type: a type out of range (a *_NUM sentinel) is refused with false.

#include <cstddef>
#include <utility>

namespace RTC::Sdk {

template <typename Enum, size_t N>
const char *nameOf(Enum type, const char *const (&names)[N])
{
    const size_t index = static_cast<size_t>(type);
    return index < N ? names[index] : "";
}

template <typename Holders, typename Enum, typename Listener>
bool addTo(Holders &holders, Enum type, Listener *listener, bool autoclean)
{
    if (static_cast<size_t>(type) >= holders.size())
        return false;
    holders[static_cast<size_t>(type)].addListener(listener, autoclean);
    return true;
}

template <typename Holders, typename Enum, typename Listener>
bool removeFrom(Holders &holders, Enum type, Listener *listener)
{
    if (static_cast<size_t>(type) >= holders.size())
        return false;
    holders[static_cast<size_t>(type)].removeListener(listener);
    return true;
}

template <typename Holders, typename Enum, typename... Args>
bool notifyIn(Holders &holders, Enum type, Args &&...args)
{
    if (static_cast<size_t>(type) >= holders.size())
        return false;
    holders[static_cast<size_t>(type)].notify(std::forward<Args>(args)...);
    return true;
}

} // namespace RTC::Sdk
