// SPDX-License-Identifier: MIT
/*!
 * @file Factory.h
 * @brief coil::Factory: makes objects of registered concrete classes by identifier.
 *
 * @code
 * typedef coil::GlobalFactory<Shape> ShapeFactory;
 * ShapeFactory::instance().addFactory("circle", coil::Creator<Shape, Circle>,
 *                                     coil::Destructor<Shape, Circle>);
 * Shape* s = ShapeFactory::instance().createObject("circle");
 * ShapeFactory::instance().deleteObject(s);   // s is null afterwards
 * @endcode
 */
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

// OpenRTM-aist's export macros for plug-in modules (empty on POSIX but for EXTERN).
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

namespace coil {
/*! Results of the factory's operations. */
enum class FactoryReturn : uint8_t {
    OK,
    FACTORY_ERROR,
    ALREADY_EXISTS,
    NOT_FOUND,
    INVALID_ARG,
    UNKNOWN_ERROR
};

/*! The usual creator: a new ConcreteClass, as an AbstractClass. */
template<class AbstractClass, class ConcreteClass> AbstractClass *Creator()
{
    return new ConcreteClass();
}

/*!
 * The usual destructor: deletes @p obj and sets it to null, when it is a ConcreteClass (other
 * objects are left alone, so a factory never deletes what another one made).
 */
template<class AbstractClass, class ConcreteClass> void Destructor(AbstractClass *&obj)
{
    if (obj == nullptr || dynamic_cast<ConcreteClass *>(obj) == nullptr)
        return;
    delete obj;
    obj = nullptr;
}

/*!
 * A registry of creator/destructor pairs by identifier, which also remembers which entry made
 * each object it created, so that objects go back to the right destructor. Thread-safe.
 */
template<class AbstractClass,
         typename Identifier = std::string,
         typename Compare = std::less<Identifier>,
         typename Creator = AbstractClass *(*)(),
         typename Destructor = void (*)(AbstractClass *&)>
class Factory
{
    class FactoryEntry;

public:
    using FactoryMap = std::map<Identifier, FactoryEntry>;
    using FactoryMapIt = typename FactoryMap::iterator;
    using ObjectMap = std::map<AbstractClass *, FactoryEntry>;
    using ObjectMapIt = typename ObjectMap::iterator;

    /*! True when a creator is registered under @p id. */
    bool hasFactory(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_creators.count(id) != 0;
    }

    /*! The registered identifiers, in the map's order. */
    std::vector<Identifier> getIdentifiers()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        std::vector<Identifier> ids;
        ids.reserve(m_creators.size());
        for (FactoryMapIt it = m_creators.begin(); it != m_creators.end(); ++it)
            ids.push_back(it->first);
        return ids;
    }

    /*! The properties given with @p id's creator (empty when there is none). */
    Properties getProperties(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        FactoryMapIt it = m_creators.find(id);
        return it == m_creators.end() ? Properties() : it->second.prop_;
    }

    /*! Registers @p creator and @p destructor under @p id (INVALID_ARG for null functions). */
    FactoryReturn addFactory(const Identifier &id, Creator creator, Destructor destructor,
                             Properties prop = Properties())
    {
        if (!creator || !destructor)
            return FactoryReturn::INVALID_ARG;
        std::lock_guard<std::mutex> guard(m_mutex);
        if (m_creators.count(id) != 0)
            return FactoryReturn::ALREADY_EXISTS;
        m_creators[id] = FactoryEntry(id, creator, destructor, prop);
        return FactoryReturn::OK;
    }

    /*! Unregisters @p id; objects it made can still be deleted with deleteObject(obj). */
    FactoryReturn removeFactory(const Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_creators.erase(id) != 0 ? FactoryReturn::OK : FactoryReturn::NOT_FOUND;
    }

    /*! A new object from @p id's creator, or null when @p id is unknown. */
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

    /*!
     * Deletes @p obj with @p id's destructor (with the destructor of the entry that made it
     * when @p id is unknown) and sets @p obj to null.
     */
    FactoryReturn deleteObject(const Identifier &id, AbstractClass *&obj)
    {
        Destructor destructor;
        {
            std::lock_guard<std::mutex> guard(m_mutex);
            FactoryMapIt it = m_creators.find(id);
            if (it == m_creators.end())
                destructor = Destructor();
            else
                destructor = it->second.destructor_;
            if (destructor)
                m_objects.erase(obj);
        }
        if (!destructor)
            return deleteObject(obj);
        destructor(obj);
        return FactoryReturn::OK;
    }

    /*! Deletes @p obj with the destructor of the entry that made it; NOT_FOUND for others. */
    FactoryReturn deleteObject(AbstractClass *&obj)
    {
        Destructor destructor;
        {
            std::lock_guard<std::mutex> guard(m_mutex);
            ObjectMapIt it = m_objects.find(obj);
            if (it == m_objects.end())
                return FactoryReturn::NOT_FOUND;
            destructor = it->second.destructor_;
            m_objects.erase(it);
        }
        // Outside the lock: an object's destructor may use the factory.
        destructor(obj);
        return FactoryReturn::OK;
    }

    /*! The objects made and not yet deleted through this factory. */
    std::vector<AbstractClass *> createdObjects()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        std::vector<AbstractClass *> objects;
        objects.reserve(m_objects.size());
        for (ObjectMapIt it = m_objects.begin(); it != m_objects.end(); ++it)
            objects.push_back(it->first);
        return objects;
    }

    /*! True when this factory made @p obj (and it was not deleted since). */
    bool isProducerOf(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_objects.count(obj) != 0;
    }

    /*! The identifier @p obj was made under. */
    FactoryReturn objectToIdentifier(AbstractClass *obj, Identifier &id)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        if (it == m_objects.end())
            return FactoryReturn::NOT_FOUND;
        id = it->second.id_;
        return FactoryReturn::OK;
    }

    /*! The creator that made @p obj (a null one for objects this factory did not make). */
    Creator objectToCreator(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        return it == m_objects.end() ? Creator() : it->second.creator_;
    }

    /*! The destructor for @p obj (a null one for objects this factory did not make). */
    Destructor objectToDestructor(AbstractClass *obj)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        ObjectMapIt it = m_objects.find(obj);
        return it == m_objects.end() ? Destructor() : it->second.destructor_;
    }

private:
    class FactoryEntry
    {
    public:
        FactoryEntry()
            : id_()
            , creator_()
            , destructor_()
        { }
        FactoryEntry(Identifier id, Creator creator, Destructor destructor, const Properties &prop)
            : id_(std::move(id))
            , creator_(creator)
            , destructor_(destructor)
            , prop_(prop)
        { }
        Identifier id_;
        Creator creator_;
        Destructor destructor_;
        Properties prop_;
    };

    FactoryMap m_creators;
    ObjectMap m_objects;
    std::mutex m_mutex;
};

/*! A Factory with one process-wide instance, for plug-in registries. */
template<class AbstractClass,
         typename Identifier = std::string,
         typename Compare = std::less<Identifier>,
         typename Creator = AbstractClass *(*)(),
         typename Destructor = void (*)(AbstractClass *&)>
class GlobalFactory : public Factory<AbstractClass, Identifier, Compare, Creator, Destructor>
{
public:
    /*!
     * The instance, created on first use and kept for the life of the process: modules may still
     * unregister from it while static objects are destroyed at exit.
     */
    static GlobalFactory &instance()
    {
        static GlobalFactory *const factory = new GlobalFactory();
        return *factory;
    }

private:
    GlobalFactory() = default;
    ~GlobalFactory() = default;
    GlobalFactory(const GlobalFactory &) = delete;
    GlobalFactory &operator=(const GlobalFactory &) = delete;
};
} // namespace coil

#endif // COIL_FACTORY_H
