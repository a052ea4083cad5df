// SPDX-License-Identifier: MIT
// A thread-safe list of listener objects, some of which the list deletes.
#ifndef RTM_UTIL_LISTENERHOLDER_H
#define RTM_UTIL_LISTENERHOLDER_H

#include <mutex>
#include <utility>
#include <vector>

namespace RTM {
namespace util {
/**
 * Listeners of class @p ListenerClass in the order they were added. A listener added with
 * autoclean belongs to the holder: it is deleted when removed or when the holder goes.
 * Subclasses call the listeners with LISTENERHOLDER_CALLBACK.
 */
template<typename ListenerClass> class ListenerHolder
{
public:
    using Entry = std::pair<ListenerClass *, bool>;
    using EntryList = std::vector<Entry>;
    using EntryIterator = typename EntryList::iterator;

    ListenerHolder() = default;
    ListenerHolder(ListenerHolder const &) = delete;
    ListenerHolder &operator=(ListenerHolder const &) = delete;
    virtual ~ListenerHolder()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        for (Entry &entry : m_listeners) {
            if (entry.second)
                delete entry.first;
        }
        m_listeners.clear();
    }

    virtual void addListener(ListenerClass *listener, bool autoclean)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_listeners.emplace_back(listener, autoclean);
    }
    virtual void removeListener(ListenerClass *listener)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        for (EntryIterator it = m_listeners.begin(); it != m_listeners.end(); ++it) {
            if (it->first != listener)
                continue;
            if (it->second)
                delete it->first;
            m_listeners.erase(it);
            return;
        }
    }

protected:
    std::mutex m_mutex;
    EntryList m_listeners;
};
} // namespace util
} // namespace RTM

/// Calls member @p func with @p args (in parentheses) on every listener, under the holder's lock.
#define LISTENERHOLDER_CALLBACK(func, args)                                                        \
    do {                                                                                           \
        std::lock_guard<std::mutex> guard(m_mutex);                                                \
        for (auto &&listener : m_listeners) {                                                      \
            listener.first->func args;                                                             \
        }                                                                                          \
    } while (0)

#endif // RTM_UTIL_LISTENERHOLDER_H
