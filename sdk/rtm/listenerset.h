// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

namespace RTC::Sdk {

/**
 * Listener objects of one event, as OpenRTM-aist's add…Listener(listener, autoclean) keeps them:
 * with autoclean the set deletes the listener when it is removed or when the set goes. Not
 * thread-safe: its owner locks.
 */
template <typename Listener>
class ListenerSet
{
public:
    ListenerSet() = default;
    ListenerSet(const ListenerSet &) = delete;
    ListenerSet &operator=(const ListenerSet &) = delete;
    ~ListenerSet()
    {
        for (auto &entry : m_entries) {
            if (entry.second)
                delete entry.first;
        }
    }

    void add(Listener *listener, bool autoclean)
    {
        if (listener != nullptr)
            m_entries.emplace_back(listener, autoclean);
    }
    bool remove(Listener *listener)
    {
        auto it = std::find_if(m_entries.begin(), m_entries.end(),
                               [listener](const auto &entry) { return entry.first == listener; });
        if (it == m_entries.end())
            return false;
        if (it->second)
            delete it->first;
        m_entries.erase(it);
        return true;
    }
    bool empty() const { return m_entries.empty(); }
    /// Calls @p call with each listener in the order they were added.
    template <typename Call>
    void forEach(Call call) const
    {
        for (const auto &entry : m_entries)
            call(*entry.first);
    }

private:
    std::vector<std::pair<Listener *, bool>> m_entries;
};

} // namespace RTC::Sdk
