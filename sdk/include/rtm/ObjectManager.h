// SPDX-License-Identifier: MIT
// A thread-safe list of objects found by an identifier through a predicate.
#ifndef RTC_OBJECTMANAGER_H
#define RTC_OBJECTMANAGER_H

#include <rtm/RTC.h>

#include <mutex>

#include <algorithm>
#include <vector>
#include <string>

/**
 * The objects a manager keeps (components, factories, …), each at most once. @p Predicate is
 * constructed from an Object* or an Identifier and tells whether an object is the one meant.
 */
template <typename Identifier, typename Object, typename Predicate>
class ObjectManager
{
public:
    using ObjectVector = std::vector<Object *>;
    using ObjectVectorItr = typename ObjectVector::iterator;
    using ObjectVectorConstItr = typename ObjectVector::const_iterator;

    ObjectManager() = default;
    ~ObjectManager() = default;

    /// Adds @p obj unless an equal one (by the predicate) is listed; false then.
    bool registerObject(Object *obj)
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        if (std::find_if(m_objects._obj.begin(), m_objects._obj.end(), Predicate(obj)) != m_objects._obj.end())
            return false;
        m_objects._obj.push_back(obj);
        return true;
    }

    /// Takes the object known as @p id off the list and returns it; null when none is.
    Object *unregisterObject(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        ObjectVectorItr it = std::find_if(m_objects._obj.begin(), m_objects._obj.end(), Predicate(id));
        if (it == m_objects._obj.end())
            return nullptr;
        Object *obj = *it;
        m_objects._obj.erase(it);
        return obj;
    }

    /// The object known as @p id; null when none is.
    Object *find(const Identifier &id) const
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        ObjectVectorConstItr it = std::find_if(m_objects._obj.begin(), m_objects._obj.end(), Predicate(id));
        return it == m_objects._obj.end() ? nullptr : *it;
    }

    /// A copy of the list, in the order of registration.
    std::vector<Object *> getObjects() const
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        return m_objects._obj;
    }

    /// Calls @p p on every object, under the list's lock.
    template <class Pred>
    Pred for_each(Pred p)
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        return std::for_each(m_objects._obj.begin(), m_objects._obj.end(), p);
    }
    template <class Pred>
    Pred for_each(Pred p) const
    {
        std::lock_guard<std::mutex> guard(m_objects._mutex);
        return std::for_each(m_objects._obj.begin(), m_objects._obj.end(), p);
    }

protected:
    struct Objects
    {
        mutable std::mutex _mutex;
        ObjectVector _obj;
    };
    Objects m_objects;
};

#endif // RTC_OBJECTMANAGER_H
