// SPDX-License-Identifier: MIT
// A registry of creator/destructor pairs by identifier, and the objects made through it
// (OpenRTM-aist's coil::Factory); GlobalFactory is the process-wide one per product type.
#ifndef COIL_FACTORY_H
#define COIL_FACTORY_H

#include <coil/Properties.h>
#include <coil/Singleton.h>

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

// Explicit instantiations of factories live in the library that owns them; users' code sees them
// as `extern template`, so that every module shares the library's one instance.
#ifndef DLL_PLUGIN
#define DLL_PLUGIN
#endif
#ifndef EXTERN
#ifdef LIBRARY_EXPORTS
#define EXTERN
#else
#define EXTERN extern
#endif
#endif

namespace coil
{
/// What the factory operations report.
enum class FactoryReturn : uint8_t
{
    OK,
    FACTORY_ERROR,
    ALREADY_EXISTS,
    NOT_FOUND,
    INVALID_ARG,
    UNKNOWN_ERROR
};

/// A creator for addFactory(): a new ConcreteClass.
template <class AbstractClass, class ConcreteClass>
AbstractClass *Creator()
{
    return new ConcreteClass();
}

/// A destructor for addFactory(): deletes `obj` if it is a ConcreteClass and clears the pointer.
template <class AbstractClass, class ConcreteClass>
void Destructor(AbstractClass *&obj)
{
    if (obj == nullptr || dynamic_cast<ConcreteClass *>(obj) == nullptr)
        return;
    delete obj;
    obj = nullptr;
}

/// Creators by identifier, and which creator made each object still alive. Thread-safe.
template <class AbstractClass, typename Identifier = std::string,
          typename Compare = std::less<Identifier>, typename Creator = AbstractClass *(*)(),
          typename Destructor = void (*)(AbstractClass *&)>
class Factory
{
    struct FactoryEntry
    {
        Identifier id_;
        Creator creator_;
        Destructor destructor_;
        Properties prop_;
    };

public:
    typedef std::map<Identifier, FactoryEntry, Compare> FactoryMap;
    typedef typename FactoryMap::iterator FactoryMapIt;
    typedef std::map<AbstractClass *, FactoryEntry> ObjectMap;
    typedef typename ObjectMap::iterator ObjectMapIt;

    /// Whether a creator is registered as `id`.
    bool hasFactory(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_creators.count(id) != 0;
    }
    /// The registered identifiers, in order.
    std::vector<Identifier> getIdentifiers()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        std::vector<Identifier> ids;
        for (FactoryMapIt it = m_creators.begin(); it != m_creators.end(); ++it)
            ids.push_back(it->first);
        return ids;
    }
    /// The properties registered with `id` (empty when there is none).
    Properties getProperties(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        FactoryMapIt it = m_creators.find(id);
        return it == m_creators.end() ? Properties() : it->second.prop_;
    }
    /// Registers a creator; ALREADY_EXISTS leaves the first one, INVALID_ARG for null functions.
    FactoryReturn addFactory(const Identifier &id, Creator creator, Destructor destructor,
                             Properties prop = Properties())
    {
        if (creator == nullptr || destructor == nullptr)
            return FactoryReturn::INVALID_ARG;
        std::lock_guard<std::mutex> guard(m_mutex);
        if (m_creators.count(id) != 0)
            return FactoryReturn::ALREADY_EXISTS;
        FactoryEntry entry = {id, creator, destructor, prop};
        m_creators.insert(std::make_pair(id, entry));
        return FactoryReturn::OK;
    }
    /// Unregisters `id`; objects made by it can still be deleted through deleteObject(obj).
    FactoryReturn removeFactory(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_creators.erase(id) != 0 ? FactoryReturn::OK : FactoryReturn::NOT_FOUND;
    }
    /// A new object of the kind registered as `id`, or nullptr.
    AbstractClass *createObject(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        FactoryMapIt it = m_creators.find(id);
        if (it == m_creators.end())
            return nullptr;
        AbstractClass *obj = it->second.creator_();
        if (obj != nullptr)
            m_objects[obj] = it->second;
        return obj;
    }
    /// Deletes `obj` with the destructor registered as `id` (or the one that made it) and clears it.
    FactoryReturn deleteObject(const Identifier &id, AbstractClass *&obj)
    {
        std::unique_lock<std::mutex> guard(m_mutex);
        FactoryMapIt it = m_creators.find(id);
        if (it == m_creators.end()) {
            guard.unlock();
            return deleteObject(obj);
        }
        AbstractClass *made = obj;
        it->second.destructor_(obj);
        m_objects.erase(made);
        return FactoryReturn::OK;
    }
    /// Deletes `obj` with the destructor of the creator that made it and clears it.
    FactoryReturn deleteObject(AbstractClass *&obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        if (it == m_objects.end())
            return FactoryReturn::NOT_FOUND;
        Destructor destructor = it->second.destructor_;
        m_objects.erase(it);
        destructor(obj);
        return FactoryReturn::OK;
    }
    /// The objects made here and not deleted yet.
    std::vector<AbstractClass *> createdObjects()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        std::vector<AbstractClass *> objects;
        for (ObjectMapIt it = m_objects.begin(); it != m_objects.end(); ++it)
            objects.push_back(it->first);
        return objects;
    }
    /// Whether `obj` was made here and is not deleted yet.
    bool isProducerOf(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_objects.count(obj) != 0;
    }
    /// The identifier `obj` was made under.
    FactoryReturn objectToIdentifier(AbstractClass *obj, Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        if (it == m_objects.end())
            return FactoryReturn::NOT_FOUND;
        id = it->second.id_;
        return FactoryReturn::OK;
    }
    /// The creator and destructor that belong to `obj` (null when it was not made here).
    Creator objectToCreator(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        return it == m_objects.end() ? Creator() : it->second.creator_;
    }
    Destructor objectToDestructor(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        return it == m_objects.end() ? Destructor() : it->second.destructor_;
    }

private:
    FactoryMap m_creators;
    ObjectMap m_objects;
    std::mutex m_mutex;
};

/// The process-wide Factory of one product type.
template <class AbstractClass, typename Identifier = std::string,
          typename Compare = std::less<Identifier>, typename Creator = AbstractClass *(*)(),
          typename Destructor = void (*)(AbstractClass *&)>
class GlobalFactory : public Factory<AbstractClass, Identifier, Compare, Creator, Destructor>
{
public:
    /// The one instance, made on first use and kept for the life of the process (modules may
    /// still unregister from it while static objects are destroyed).
    static GlobalFactory &instance();

private:
    GlobalFactory() {}
    ~GlobalFactory() {}
    GlobalFactory(const GlobalFactory &);
    GlobalFactory &operator=(const GlobalFactory &);
};

template <class AbstractClass, typename Identifier, typename Compare, typename Creator, typename Destructor>
GlobalFactory<AbstractClass, Identifier, Compare, Creator, Destructor> &
GlobalFactory<AbstractClass, Identifier, Compare, Creator, Destructor>::instance()
{
    static GlobalFactory *const factory = new GlobalFactory();
    return *factory;
}
} // namespace coil

#endif // COIL_FACTORY_H
